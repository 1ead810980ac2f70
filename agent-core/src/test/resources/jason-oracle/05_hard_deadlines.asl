// goals with a hard deadline: one outlives it as its own intention, one ends in time, one outlives it as a subgoal
!start.
+!start <- !!slow[hard_deadline(500)]; !quick(1)[hard_deadline(2000)]; .print(quick_done);
           !slow2[hard_deadline(300)]; .print(after); .wait(2500); .print(still_here); .stopMAS.
+!quick(X) <- .wait(100); .print(quick, X).
+!slow <- .wait(2000); .print(slow_never).
+!slow2 <- .wait(1000); .print(slow2_never).
-!slow[error(E)] <- .print(slow_failed, " ", E).
-!slow2[error(E)] <- .print(slow2_failed, " ", E).
