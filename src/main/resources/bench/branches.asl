// ancestor/2 over a chain whose every link has dead ends that are tried first: at each level the
// proof backtracks out of them before it takes the link that goes on.
length(100).
branches(5).
queries(40).
ancestor(X, Y) :- parent(X, Y).
ancestor(X, Y) :- parent(X, Z) & ancestor(Z, Y).
!bench.
+!bench : length(N) & branches(B) <-
    for (.range(I, 1, N)) {
        +parent(I, I + 1);
        // +b adds a belief first: the dead ends (negative numbers) come before the link
        for (.range(K, 1, B)) { +parent(I, 0 - (I * B + K)) }
    };
    .print(start);
    !query(0).
+!query(Q) : queries(Q) <- .print(end); .stopMAS.
+!query(K) : length(N) <- ?ancestor(1, N + 1); !query(K + 1).
