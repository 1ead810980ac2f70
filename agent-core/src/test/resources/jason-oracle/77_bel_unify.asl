// Queries with partially bound literals, annotations with variables, and strong negation in rules.
p(a, 1)[x(1)]. p(b, 2)[x(2)]. ~p(c, 3).
q(X) :- ~p(X, _).
!start.
+!start <- ?p(W, 2)[x(A)]; .print(W, " ", A); ?q(Z); .print(Z);
    .findall(K, p(K, _)[x(_)], L); .print(L); .stopMAS.
