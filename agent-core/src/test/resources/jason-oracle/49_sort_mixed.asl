// The standard order of terms with mixed types.
!start.
+!start <-
    .sort([b, 3, "s", [1], f(x), a, 1.5, "a", [], g(1, 2), g(1)], L); .print(L);
    .sort([f(2), f(1, 1), f(1), ~f(1)], M); .print(M);
    .max([1, a, "z"], X); .print(X);
    .stopMAS.
