// .member's solutions one by one (in a findall, a for, a body), and .delete by index, by a ground
// term and by a pattern whose variables keep their first match's values, as Jason's do.
!start.
+!start <-
    .findall(Y, .member(Y, [3, 1, 2]) & Y > 1, L); .print(L);
    for (.member(p(Z), [p(1), q(2), p(3)])) { .print(z(Z)) };
    .member(W, [x, y]); .print(first(W));
    .delete(p(_), [p(1), q(2), p(3)], D); .print(D);
    .delete(2, [a, b, c, d], D2); .print(D2);
    .delete(p(X), [p(1), p(1), p(2)], D3); .print(D3, " ", X);
    .delete(a, [a, b, a, c], D4); .print(D4);
    .delete("an", "banana", D5); .print(D5);
    .findall(M, .member(M, [1, 2, 3]), Ms); .print(Ms);
    .member(f(A, B), [g(1), f(2, 3), f(4, 5)]); .print(A, B);
    .stopMAS.
