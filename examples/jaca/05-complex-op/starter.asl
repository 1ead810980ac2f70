!start.
+!start <- makeArtifact("job", "demo.TwoStepJob", [], J); focus(J); run(10); println("run completed"); +completed; !finish.
+first_step_done(C) <- println("first step done, contributions so far: ", C); .send(helper, tell, ready).
+second_step_done(C) <- println("second step done, contributions: ", C); +second_seen; !finish.
+finished[source(helper)] <- !finish.
// the run ends when the operation completed, its second step's signal was perceived and the
// helper is done: three intentions, in whichever order they get there
+!finish : completed & second_seen & finished[source(helper)] <- .stopMAS.
+!finish.
