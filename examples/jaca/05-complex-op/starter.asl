!start.
+!start <- makeArtifact("job", "demo.TwoStepJob", [], J); focus(J); run(10); println("run completed").
+first_step_done(C) <- println("first step done, contributions so far: ", C); .send(helper, tell, ready).
+second_step_done(C) <- println("second step done, contributions: ", C).
+finished[source(helper)] <- .wait(100); .stopMAS.
