// A variable bound only to other free variables is applied as itself (Jason's capply): the term made
// no longer links them. Printing, adding a belief, posting a goal and findall's template show it.
!go.
+!go <- X = Y; .print(X, " ", Y); B = A; .print(A, " ", B);
   .member(T, [_]); .print(T); L = [_, W]; .print(L);
   P = Q; +p(P, Q); ?p(C, D); C = 5; .print(D);
   .findall(q(X2, Y2), X2 = Y2, F); .print(F);
   E = G; !h(E, G); .print(E, " ", G);
   !t(["a", "b"], "", Text); .print(Text);
   !u(V); .print(V);
   .stopMAS.
+!h(H1, H2) <- H1 = 1; .print("H2=", H2).
+!t([], S, S).
+!t([S1|R], S0, S) <- .concat(S0, S1, S2); !t(R, S2, S).
+!u(U) <- !v(U).
+!v(Z) <- Z = 5.
