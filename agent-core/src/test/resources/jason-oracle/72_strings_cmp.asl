// Strings: comparison, sorting and equality with atoms.
!start.
+!start <- .sort(["b", "a", "B", "ab"], L); .print(L);
    if ("abc" == "abc") { .print(eq) };
    if ("abc" \== abc) { .print(differ) };
    .concat([1], [2, [3]], C); .print(C);
    .stopMAS.
