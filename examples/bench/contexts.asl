// 20 000 beliefs added in a for, each handled by a plan chosen by a one-relation context.
!go.
+!go <- .print(start); for (.range(I, 1, 20000)) { +item(I) }; .print(end); .stopMAS.
+item(I) : I mod 2 == 0 <- -item(I).
+item(I) <- true.
