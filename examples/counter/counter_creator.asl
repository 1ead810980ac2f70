// Makes the counter "c0" and increments it three times, slowly enough for the user to see each value.
!setup.

+!setup <- makeArtifact("c0", "jacabot.cartago.examples.Counter", [], C); !use(C, 3).

+!use(_, 0).
+!use(C, N) <- .wait(100); inc[artifact_id(C)]; !use(C, N - 1).
