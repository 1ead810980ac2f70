// ancestor/2 over a chain of parent facts, asked from one end to the other, so that each proof is
// as deep as the chain. `bench interpreter` runs copies with other lengths and query counts.
length(100).
queries(200).
ancestor(X, Y) :- parent(X, Y).
ancestor(X, Y) :- parent(X, Z) & ancestor(Z, Y).
!bench.
+!bench : length(N) <- for (.range(I, 1, N)) { +parent(I, I + 1) }; .print(start); !query(0).
+!query(Q) : queries(Q) <- .print(end); .stopMAS.
+!query(K) : length(N) <- ?ancestor(1, N + 1); !query(K + 1).
