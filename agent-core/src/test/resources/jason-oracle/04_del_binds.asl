c(0).
d(a, 1).
!start.
+!start <- -c(N); .print(N); +c(N + 1); ?next(M); .print(M); ?next(K); .print(K);
           -d(X, Y)[source(S)]; .print(X, " ", Y, " ", S);
           -+e(1); -e(Z); .print(Z); .stopMAS.
+?next(N) <- -c(N); +c(N + 1).
