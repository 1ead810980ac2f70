// Skill: the initial phase and the motion loop (thesis Chapter 4 §5, "Common Aspects": "the
// procedure to create the artifact and put the focus on it ... we can call it, the initial phase").
// Every experiment agent includes it first.
// Reads: middlewareClass(C), the middleware artifact of the agent's experiment.
// Once connected, every setUpGoal(G) belief (a skill declares its own) is achieved, in the order of
// the includes, before the data flows. The +!move(R) plans that choose what the robot does are the
// skills'; the first applicable one wins, so the order of the includes is the order of priority.

maxSpeed(100).         // the wheel speed command's top
middlewarePort(4444).  // where the middleware listens (the thesis')
connectionPoll(100).   // ms between looks for connected(true) (§5; Appendix B: 500)
// (Parameters above, plans below.)

@start +!start <- !init(Id); focus(Id); println("focus achieved"); accept; !waitConnection.

// The experiment runner may have made the middleware already (lockstep runs); otherwise make it.
@findMiddleware +!init(Id) <- lookupArtifact("middleware", Id).
@makeMiddleware
-!init(Id) : middlewarePort(P) & middlewareClass(C)
    <- makeArtifact("middleware", C, [P], Id);
       println("Artifact created").
@startFailed -!start[error_msg(M)] <- println("the robot cannot start: ", M); .stopMAS.

@connected
+!waitConnection : connected(true)
    <- println("Connection successful, waiting for sensor data"); for (setUpGoal(G)) { !G }; acquireData; !moving.
@awaitConnection +!waitConnection : connectionPoll(T) <- .wait(T); !waitConnection.

// The motion loop (Chapter 5 §2 and Appendix B, +!moving): a random number chooses among the moves of random motion;
// the +!move plans of the other skills suspend it while a more relevant task runs.
@moving +!moving <- while (true) { .random(R); !move(R) }.
// A move that fails is reported once per kind of failure (error and error_msg annotations), and
// the loop backs off half a second, so a move that fails again and again is no failure storm.
@moveFailed
-!move(_)[error(E), error_msg(M)] : not moveFailed(E)
    <- +moveFailed(E); println("move failed: ", E, " ", M); .wait(500).
@moveFailedAgain -!move(_) <- .wait(500).
