// A recursive rule (ancestor) over 1 000 parent facts, queried 10 000 times.
ancestor(X, Y) :- parent(X, Y).
ancestor(X, Y) :- parent(X, Z) & ancestor(Z, Y).
!bench.
+!bench <- for (.range(I, 1, 1000)) { +parent(I, I + 1) }; .print(start); !query(0).
+!query(10000) <- .print(end); .stopMAS.
+!query(N) <- ?ancestor(995, 1000); !query(N + 1).
