// 200 000 tail-recursive subgoals.
!count(0).
+!count(200000) <- .stopMAS.
+!count(N) <- !count(N + 1).
