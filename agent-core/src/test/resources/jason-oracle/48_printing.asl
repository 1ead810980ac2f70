// Printing terms: negative numbers, nested lists, strings inside structures, annotations, operators.
!start.
+!start <-
    .print(f(-1, -2.5), " ", [[-1], [a, "b"]], " ", p(X)[a, b(1)]);
    .print(g("x y", 'q a', c), " ", ~h(1), " ", [1, 2 | T]);
    X = 1 + 2 * Y; .print(X);
    .term2string(f(1, "two", [3]), S); .print(S);
    .print(1.0e10, " ", 123456789, " ", 0.000123, " ", -0.0);
    .stopMAS.
