// A recursive rule (ancestor) over 1 000 parent facts, queried 10 000 times.
!setup.
+!setup <- for (.range(I, 1, 1000)) { +parent(I, I + 1) }; !query(0).
ancestor(X, Y) :- parent(X, Y).
ancestor(X, Y) :- parent(X, Z) & ancestor(Z, Y).
+!query(10000) <- .stopMAS.
+!query(N) <- ?ancestor(995, 1000); !query(N + 1).
