// Relations in a plan body (=, ==, \==, <, >=, =..), each binding in the intention's unifier or
// failing with Jason's message, conditions of if/elif/else and while, and contexts of one relation.
i(0).
!start.
+!start <-
    X = f(Y); Y = 2; .print(X);
    A = 3 * 4 - 1; B = A mod 5; .print(A, " ", B);
    [H|T] = [1, 2, 3]; .print(H, " ", T);
    p(Q, r(W)) =.. L; .print(L);
    K =.. [g, [1, Z], []]; Z = 9; .print(K);
    N = 5; N == 5; N \== 6; N >= 5; N < 6; "b" > "a"; .print(compared);
    if (C = 10 & D = C + 1) { .print(then(C, D)) } else { .print(not_taken) };
    if (N > 9) { .print(not_taken) } elif (N = E) { .print(in_elif(E)) } else { .print(not_taken) };
    if (N > 9) { .print(not_taken) } else { .print(else_ran) };
    if (not (N > 9)) { .print(not_ran) };
    if (N < 9 | G = 1) { .print(or_ran(G)) };
    while (i(I) & I < 3) { .print(turn(I)); J = I + 1; -+i(J) };
    ?i(Last); .print(after_loop(Last));
    !ctx(4); !ctx(1); !ctx(f(1)); !ctx(a);
    !fails1; !fails2; !fails3.
// contexts of one relation, binding for the body or choosing the plan
+!ctx(N) : N = f(A) <- .print(ctx_unified(A)).
+!ctx(N) : N > 3 & M = 1 <- .print(ctx_both(N, M)).
+!ctx(N) : M = N * 2 <- .print(ctx_bound(M)).
+!ctx(N) : N == a <- .print(ctx_atom).
-!ctx(N)[error(E)] <- .print(ctx_failed(N, E)).
+!fails1 <- V = 1; V = 2; .print(not_reached).
-!fails1[error(E), error_msg(Msg)] <- .print(E); .print(Msg).
+!fails2 <- V = 1; V > 3; .print(not_reached).
-!fails2[error(E), error_msg(Msg)] <- .print(E); .print(Msg).
+!fails3 <- V = g(1); g(W) = V; W == 2; .print(not_reached).
-!fails3[error(E), error_msg(Msg)] <- .print(E); .print(Msg); .stopMAS.
