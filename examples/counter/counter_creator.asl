// Makes the counter "c0" and, once the user observes it, increments it three times.
!setup.

+!setup <- makeArtifact("c0", "jacabot.cartago.examples.Counter", [], C); +counter(C).

// The user says when it has focused the counter, so that it sees every value, whatever the load.
+ready[source(counter_user)] <- ?counter(C); !use(C, 3).
// The user may find "c0" before this agent has noted it in counter(C) (makeArtifact and the note
// are two steps): wait for the note, as the user waits for the artifact.
+?counter(C) <- .wait(10); ?counter(C).

+!use(_, 0).
+!use(C, N) <- .wait(50); inc[artifact_id(C)]; !use(C, N - 1).
