// -+ generates a deletion event and an addition event; order of their plans.
c(0).
!start.
+!start <- -+c(1); .print(s1); -+c(2); .print(s2); .stopMAS.
+c(X) <- .print("+c ", X).
-c(X) <- .print("-c ", X).
