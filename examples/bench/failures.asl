// 20 000 subgoals, every other one failing and recovered by a failure plan.
!go.
+!go <- .print(start); !t(0).
+!t(20000) <- .print(end); .stopMAS.
+!t(N) <- !risky(N); !t(N + 1).
+!risky(N) : N mod 2 == 0 <- .fail.
+!risky(N) <- true.
-!risky(N) <- true.
