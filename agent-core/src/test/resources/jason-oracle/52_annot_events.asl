// Belief events carry annotations; plans select by annotation.
!start.
+!start <- +b(1)[a]; +b(1)[c]; +b(2)[source(x)]; -b(1)[a]; .print(done); .stopMAS.
+b(X)[source(self)] <- .print("self ", X).
+b(X)[source(S)] <- .print("from ", S, " ", X).
-b(X)[A] <- .print("-b ", X, " ", A).
