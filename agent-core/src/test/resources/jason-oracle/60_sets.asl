// Set and list actions: union, intersection, difference, delete, nth, setof.
!start.
+!start <-
    .union([c, a], [b, a], U); .intersection([c, a, b], [b, x, c], I); .difference([c, a, b], [a], D); .print(U, " ", I, " ", D);
    .delete(a, [a, b, a, c], L1); .delete(1, [x, y, z], L2); .print(L1, " ", L2);
    .setof(X, .member(X, [3, 1, 3, 2]), S); .print(S);
    .nth(N, [p, q, r], q); .print(N);
    .concat("a", 1, f(x), S2); .print(S2);
    .reverse("abc", R); .print(R);
    .stopMAS.
