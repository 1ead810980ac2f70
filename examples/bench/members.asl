// 20 000 turns of .member (the first solution, and a ground one) and .delete over a 100-element list.
!go.
+!go <- .findall(X, .range(X, 1, 100), L); +list(L); .print(start); !m(0).
+!m(20000) <- .print(end); .stopMAS.
+!m(N) : list(L) <- .member(X, L); .member(50, L); .delete(7, L, L2); !m(N + 1).
