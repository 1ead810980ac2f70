// 200 000 tail-recursive subgoals.
!bench.
+!bench <- .print(start); !count(0).
+!count(200000) <- .print(end); .stopMAS.
+!count(N) <- !count(N + 1).
