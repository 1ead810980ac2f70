// Each of 1 000 agents counts to 1 000; the last to finish stops the system.
!count(0).
+!count(1000) <- .send(supervisor, tell, finished).
+!count(N) <- !count(N + 1).
