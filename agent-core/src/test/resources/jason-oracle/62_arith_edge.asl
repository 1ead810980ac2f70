// Arithmetic edge cases.
!start.
+!start <- .print(7 / 2, " ", -7 / 2, " ", 1.0e15, " ", 2 ** 62, " ", 10 mod 3, " ", 10.5 mod 3);
    .print(math.round(-0.5), " ", math.abs(-0.0), " ", 3 - 3.0, " ", 0.1 * 3); .stopMAS.
