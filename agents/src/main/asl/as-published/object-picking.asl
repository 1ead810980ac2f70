// Experiment 2: red-cylinder picking (thesis Chapter 4 §2), with the Khepera.
// On top of random motion and obstacle avoidance: a red cylinder seen ahead (central sensor and
// camera) is signalled by cylinderDetected and picked: stop, catch (open and lower the gripper,
// close it), check the grip within a time limit (caught), raise the arm and check it is up
// (picked). A lateral cylinder (cylinderLeft / cylinderRight) makes the robot turn towards it
// first, giving up when it is beyond reach (cylinderBeyond). Failures: the cylinder moved away
// (no grip in time: open, turn around, resume), the arm does not rise, the carried cylinder
// falls (fallen: an atomic plan drops everything, stops and reports).
// Our own agent to the thesis' strategy. Fixed from the listings: "+reachCylinder(b)" that
// added a second reachCylinder belief is "-+reachCylinder(b)"; the obstacle plan ignores
// obstacles while reaching a cylinder ("not reachCylinder(true)", as the text says).
// Tuning (not in the thesis): the obstacle, lateral-cylinder and cylinderDetected plans end the random motion that runs (.succeed_goal(move(_)));
// "avoiding" only suspends the next move, so a move plan in its .wait would later send
// "forward" in the middle of the avoiding turn (Chapter 4 §1.2; see obstacle-avoidance.asl).
// cylinderBeyond is signalled when the lateral cylinder, turned towards, reaches the centre of
// the camera image: the robot approaches it slowly (the listing's setSpeeds(M/5, M/5)) until
// cylinderDetected, 8 s at most. The listing's "turnAround; .wait(20000)" before that would turn
// the robot's back on the cylinder it has just centred; left out.
// "+fallen" has no context: the middleware signals fallen only for a picked cylinder, and has
// already updated picked(false) when the agent handles the signal, so the listing's
// "+fallen : picked(true)" never applied and the fall went unreported.

maxSpeed(100).
reachCylinder(false).
middlewarePort(4444).

!start.

/* The initial phase (Chapter 4 §5) */

+!start <- !init(Id); focus(Id); accept; !waitConnection.

// The experiment runner may have made the middleware already (lockstep runs); otherwise make it.
+!init(Id) <- lookupArtifact("middleware", Id).
-!init(Id) : middlewarePort(P)
    <- makeArtifact("middleware", "jacabot.experiments.ObjectPickingMiddleware", [P], Id);
       println("Artifact created").
-!start[error_msg(M)] <- println("the robot cannot start: ", M); .stopMAS.

+!waitConnection : connected(true)
    <- println("Connection successful, waiting for sensor data"); acquireData; !moving.
+!waitConnection <- .wait(100); !waitConnection.

/* Reaching a lateral or a central cylinder (Chapter 4 §2.2) */

+cylinderLeft : reachCylinder(false) & not picking
    <- -+reachCylinder(true); .succeed_goal(move(_)); stop; .print("Left Cylinder"); setSpeeds(0, 10); !reach.
+cylinderRight : reachCylinder(false) & not picking
    <- -+reachCylinder(true); .succeed_goal(move(_)); stop; .print("Right Cylinder"); setSpeeds(10, 0); !reach.
+cylinderBeyond : reachCylinder(true) & maxSpeed(M)
    <- .print("cylinder beyond"); setSpeeds(M / 5, M / 5); !approach.

+!approach <- .wait("+cylinderDetected", 8000).
-!approach <- .print("Reach lateral cylinder failed."); stop; -+reachCylinder(false).

+!reach : reachCylinder(true) <- .wait("+cylinderBeyond", 5000).
+!reach : reachCylinder(false) <- .wait("+cylinderDetected", 3000).
-!reach <- .print("Reach lateral cylinder failed."); -+reachCylinder(false).

+cylinderDetected : not picking & not picked(true)
    <- +picking; -+reachCylinder(false); .succeed_goal(move(_)); stop; .print("Cylinder detected"); catching; !block.

/* Obstacle avoidance, but not while picking or reaching a cylinder (Chapter 4 §2.2) */

+obstacle(true) : delta(D) & not avoiding & not picking & not reachCylinder(true)
    <- .print("Obstacle: ", D); +avoiding; .succeed_goal(move(_)); stop; .wait(50); !avoid(D).

+!avoid(0) <- backward; turnAround; .wait("+obstacle(false)"); -avoiding.
+!avoid(D) : D > 0 & maxSpeed(M) <- backward; setSpeeds(M / 2, -M / 2); .wait("+obstacle(false)"); -avoiding.
+!avoid(_) : maxSpeed(M) <- backward; setSpeeds(-M / 2, M / 2); .wait("+obstacle(false)"); -avoiding.

/* Random motion, suspended while a more relevant task runs */

+!moving <- while (true) { .random(R); !move(R) }.

+!move(N) : avoiding <- .wait("-avoiding"); !move(N).
+!move(N) : reachCylinder(true) <- .wait("+reachCylinder(false)"); !move(N).
+!move(N) : picking <- .wait("-picking"); .wait(50); !move(N).
+!move(N) : N <= 0.5 <- forward; .random(R); W = R * 10000; .wait(W).
+!move(N) : N <= 0.75 & N > 0.5 <- turnLeft; .random(R); W = R * 10000 / 2; .wait(W); forward; .wait(1000).
+!move(N) : N < 1 & N > 0.75 <- turnRight; .random(R); W = R * 10000 / 2; .wait(W); forward; .wait(1000).
-!move(_) <- println("move failed").

/* Picking the cylinder up, with time limits (Chapter 4 §2.1) */

+!block <- .wait("+caught(true)", 5000); !pick.
-!block <- println("block failed"); !pick.

+!pick : caught(true) <- arm_up; .wait("+picked(true)", 3500); !carry.
+!pick <- .print("Cylinder not found"); open_grip; arm_up; turnAround; .wait(2000); forward; -picking.
-!pick <- .print("Arm cannot rise"); open_grip; arm_up; turnAround; .wait(2000); forward; -picking.

+!carry : picked(true) <- println("Cylinder picked up"); -picking; forward.
+!carry <- println("Cylinder picking failed"); stop; -picking.

/* The carried cylinder has fallen: stop everything (Chapter 4 §2.2) */

@fallCylinder[atomic]
+fallen
    <- .drop_all_desires; .print("Cylinder has fallen. Anybody retrieve it"); stopAcquire; stop.
