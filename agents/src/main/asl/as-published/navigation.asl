// Experiment 3: navigation (thesis Chapter 4 §3), with the Khepera's GPS and compass.
// After picking a cylinder the robot aligns with the compass towards the storage point computed
// from GPS (computeGap, balance), goes straight, avoids obstacles and re-aligns, puts the cylinder
// down at the storage point (targetReached), turns around and leaves the area (outOfStorageArea),
// never re-entering it without a cylinder (noAccess); then it looks for the next cylinder.
// Our own agent: the Appendix B agent without the battery module, with the same fixes:
//  - "--b" and "+-b" stand for "-+b";
//  - the balance window compares the orientation O: "O > D-0.6 & O < D+0.6";
//  - "?orientation(0)" binds the orientation, and the robot turns to the opposite heading.
// Tuning (not in the thesis): the obstacle, lateral-cylinder and cylinderDetected plans end the random motion that runs (.succeed_goal(move(_)));
// "avoiding" only suspends the next move, so a move plan in its .wait would later send
// "forward" in the middle of the avoiding turn (Chapter 4 §1.2; see obstacle-avoidance.asl).
// cylinderBeyond is signalled when the lateral cylinder, turned towards, reaches the centre of
// the camera image: the robot approaches it slowly (the listing's setSpeeds(M/5, M/5)) until
// cylinderDetected, 8 s at most. The listing's "turnAround; .wait(20000)" before that would turn
// the robot's back on the cylinder it has just centred; left out.
// After avoiding an obstacle while delivering, the robot goes forward 1 s before re-aligning
// ("forward; .wait(1000)"): re-aligning at once turned it back into the obstacle it had just
// left, and it could dither for minutes in front of a box between it and the storage point.
// raiseRay also remembers the raised threshold as ray(T) (initially the threshold).
// "+fallen" has no context: the middleware signals fallen only for a picked cylinder, and has
// already updated picked(false) when the agent handles the signal, so the listing's
// "+fallen : picked(true)" never applied and the fall went unreported.

/* Initial beliefs and rules (Appendix B) */

maxSpeed(100).
storagePoint(0.41, -0.41).
threshold(0.04).
ray(0.04).
reachCylinder(false).
middlewarePort(4444).

/* Initial goals */

!start.

/* The initial phase (Chapter 4 §5, "Common Aspects") */

+!start <- !init(Id); focus(Id); println("focus achieved"); accept; !waitConnection.

// The experiment runner may have made the middleware already (lockstep runs); otherwise make it.
+!init(Id) <- lookupArtifact("middleware", Id).
-!init(Id) : middlewarePort(P)
    <- makeArtifact("middleware", "jacabot.experiments.NavigationMiddleware", [P], Id);
       println("Artifact created").
-!start[error_msg(M)] <- println("the robot cannot start: ", M); .stopMAS.

+!waitConnection : connected(true)
    <- deltaBased(false);
       ?storagePoint(X, Z); -+targetPoint(X, Z); setUpTargetPoint(X, 0, Z);
       -+reachCylinder(false);
       ?threshold(T); setThreshold(T);
       acquireData;
       !moving.
+!waitConnection <- .wait(500); !waitConnection.

/* Reaching a lateral or a central cylinder (Chapter 4 §2.1) */

+cylinderLeft : reachCylinder(false) & not insideArea
    <- -+reachCylinder(true); .succeed_goal(move(_)); stop; .print("Left Cylinder"); setSpeeds(0, 10); !reach.
+cylinderRight : reachCylinder(false) & not insideArea
    <- -+reachCylinder(true); .succeed_goal(move(_)); stop; .print("Right Cylinder"); setSpeeds(10, 0); !reach.
+cylinderBeyond : reachCylinder(true) & maxSpeed(M)
    <- .print("cylinder beyond"); setSpeeds(M / 5, M / 5); !approach.

+!approach <- .wait("+cylinderDetected", 8000).
-!approach <- .print("Reach lateral cylinder failed."); stop; -+reachCylinder(false).

+!reach : reachCylinder(true) <- .wait("+cylinderBeyond", 5000).
+!reach : reachCylinder(false) <- .wait("+cylinderDetected", 3000).
-!reach <- .print("Reach lateral cylinder failed."); -+reachCylinder(false).

+cylinderDetected : not picking & not delivering
    <- +picking; -+reachCylinder(false); .succeed_goal(move(_)); stop; .print("Cylinder detected"); catching; !block.

/* Avoiding obstacles (Chapter 4 §1.1); while delivering, re-align afterwards */

+obstacle(true) : delivering & delta(D)
    <- .drop_intention(balance); +avoiding; stop; !avoid(D); forward; .wait(1000); !computeGap; !balance; forward.
+obstacle(true) : delta(D) & not avoiding & not picking & not reachCylinder(true)
    <- .print("Obstacle: ", D); +avoiding; .succeed_goal(move(_)); stop; .wait(50); !avoid(D).

+lateralObstacle("left") <- println("high left"); !avoid(-1).
+lateralObstacle("right") <- println("high right"); !avoid(1).

/* At the storage point while delivering (Chapter 4 §3.1) */

+targetReached : delivering & orientation(O)
    <- .drop_desire(balance); .drop_desire(computeGap); .drop_desire(avoid);
       stopAcquireDistance; -delivering; .wait(100);
       .print("TARGET POINT REACHED"); stop; .wait(40);
       putDown; -desired(_); D2 = (O + 180) mod 360; +desired(D2);
       !balance; .print("balanced");
       forward; waitExit; .wait("+~around"); -~delivered.

+!raiseRay : threshold(T) <- T2 = T + 0.03; setThreshold(T2); -+ray(T2).

/* Never re-enter the storage area without a cylinder (Chapter 4 §3.1) */

+outOfStorageArea <- println("Out of target area"); restartAcquireDistance; !raiseRay; -insideArea; +~around.

@noAccess1[atomic]
+noAccess : not delivering & ~around
    <- +gettingOut; .print("Too close to storage area!! Go away!");
       stop; .wait(40); turnAround; .wait(2000); forward; .wait(1500).
+noAccess : delivering & firstTime
    <- -firstTime; +insideArea; println("Almost reached"); stopAcquireDistance.

/* Heading towards the target point with the compass (Chapter 4 §3.1) */

+!computeGap : location(X, Y, Z) & targetPoint(Tx, Tz)
    <- computeAngle(X, Z, Tx, Tz, Desired); -+desired(Desired).

+!balance : desired(D) & orientation(O) & O > D - 0.6 & O < D + 0.6
    <- stop; -~around; +firstTime; forward.
+!balance : desired(D) & orientation(O) & ((O - D >= -180 & O - D < 0) | O - D >= 180)
    <- setSpeeds(25, -10); .wait(20); !balance.
+!balance : desired(D) & orientation(O) & ((O - D < 180 & O - D > 0) | O - D < -180)
    <- setSpeeds(-10, 25); .wait(20); !balance.
+!balance <- .wait(20); !balance.

/* Random navigation, suspended while a more relevant task runs (Chapter 4 §1.1, §5) */

+!moving <- while (true) { .random(R); !move(R) }.

+!move(N) : delivering
    <- .print("Wait delivering"); .wait("-~delivered"); .print("Delivered!"); !move(N).
+!move(N) : avoiding
    <- .print("Wait avoiding"); .wait("-avoiding"); !move(N).
+!move(N) : reachCylinder(true)
    <- .print("wait lateral cyl"); .wait("+reachCylinder(false)"); !move(N).
+!move(N) : picking
    <- .print("wait picking"); .wait("-picking"); .wait(50); !move(N).
+!move(N) : N <= 0.5
    <- forward; .random(R); W = R * 10000; .wait(W).
+!move(N) : N <= 0.75 & N > 0.5
    <- turnLeft; .random(R); W = R * 10000 / 2; .wait(W); forward; .wait(1000).
+!move(N) : N < 1 & N > 0.75
    <- turnRight; .random(R); W = R * 10000 / 2; .wait(W); forward; .wait(1000).
-!move(_) <- println("move failed").

/* Picking a cylinder up (Chapter 4 §2.1) */

+!block <- .wait("+caught(true)", 5000); !pick.
-!block <- println("block failed"); !pick.

+!pick : caught(true) <- arm_up; .wait("+picked(true)", 3500); !go_ahead.
+!pick <- .print("Cylinder not found"); arm_up; turnAround; .wait(2000); -picking.
-!pick <- .print("pick failed"); !go_ahead.

+!go_ahead : picked(true)
    <- println("Cylinder picked up"); -picking; +~delivered; +delivering; !computeGap; !balance; forward.
+!go_ahead <- println("Cylinder picking failed"); stop.

/* Basic obstacle avoidance (Chapter 4 §1.2) */

+!avoid(0) <- backward; turnAround; .wait("+obstacle(false)"); -avoiding.
+!avoid(D) : D > 0 & maxSpeed(M) <- backward; setSpeeds(M / 2, -M / 2); .wait("+obstacle(false)"); -avoiding.
+!avoid(_) : maxSpeed(M) <- backward; setSpeeds(-M / 2, M / 2); .wait("+obstacle(false)"); -avoiding.

/* The carried cylinder has fallen: stop everything (Chapter 4 §2.1) */

@fallCylinder[atomic]
+fallen
    <- .drop_all_desires; .print("Cylinder has fallen. Anybody retrieve it"); stopAcquire; stop.
