// Powers, negative numbers and precedence in comparisons.
!start.
+!start <- .print((-2) ** 3, " ", 2 ** -1, " ", -3 mod 2, " ", 5 div -2);
    if (-1 < 0 & 2 ** 2 == 4) { .print(ok) };
    X = -(3); .print(X);
    .stopMAS.
