// More on strings and terms.
!start.
+!start <- .term2string(T, "p(X, [1, Y], \"s\")"); .print(T);
    if (.substring("zz", "abc")) { .print(bad) } else { .print("no zz") };
    .length("", N); .print(N);
    .concat("", "", E); .print("[", E, "]");
    .print("tab\there");
    .stopMAS.
