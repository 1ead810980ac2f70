// Experiment 1: obstacle avoidance (thesis Chapter 4 §1), with the two-sensor MyBot.
// Random motion (forward / turn left / turn right for random durations); an obstacle is
// signalled by the middleware's obstacle(true) property when the left-right difference exceeds
// the limit or a sensor passes the warning threshold; the robot turns away from the obstacle's
// side (or backs off and turns around when it is central) until obstacle(false). The coordination
// belief "avoiding" suspends random motion (Chapter 4 §1.2).
// Our own agent to the thesis' strategy; from the listing we fixed "!move" without its argument
// in the plan that waits for the end of avoidance; and the obstacle plan ends the random motion
// that runs (.succeed_goal(move(_))): the "avoiding" belief only suspends the next move, so a
// move plan already in its .wait would later send "forward; .wait(1000)" in the middle of the
// avoiding turn, and the robot drove into the wall with obstacle(true) still on, never
// signalled again (thesis §1.2 shows the same plans; the race is theirs too).

maxSpeed(100).
middlewarePort(4444).

!start.

/* The initial phase (Chapter 4 §5) */

+!start <- !init(Id); focus(Id); accept; !waitConnection.

// The experiment runner may have made the middleware already (lockstep runs); otherwise make it.
+!init(Id) <- lookupArtifact("middleware", Id).
-!init(Id) : middlewarePort(P)
    <- makeArtifact("middleware", "jacabot.experiments.ObstacleAvoidanceMiddleware", [P], Id);
       println("Artifact created").
-!start[error_msg(M)] <- println("the robot cannot start: ", M); .stopMAS.

+!waitConnection : connected(true)
    <- println("Connection successful, waiting for sensor data"); acquireData; !moving.
+!waitConnection <- .wait(100); !waitConnection.

/* Obstacle avoidance (Chapter 4 §1.2) */

+obstacle(true) : delta(V) & not avoiding
    <- +avoiding; .succeed_goal(move(_)); println("obstacle: ", V); stop; .wait(50); !avoid(V).

+!avoid(0) <- .print("Central obstacle"); backward; turnAround; .wait("+obstacle(false)"); -avoiding.
+!avoid(D) : D < 0 & maxSpeed(M) <- setSpeeds(-M / 2, M / 2); .wait("+obstacle(false)"); -avoiding.
+!avoid(_) : maxSpeed(M) <- setSpeeds(M / 2, -M / 2); .wait("+obstacle(false)"); -avoiding.

/* Random motion, suspended while avoiding (Chapter 4 §1.2, §5) */

+!moving <- while (true) { .random(R); !move(R) }.

+!move(N) : avoiding <- .wait("-avoiding"); .print("avoided"); !move(N).
+!move(N) : N <= 0.5 <- forward; .random(R); W = R * 10000; .wait(W).
+!move(N) : N <= 0.75 & N > 0.5 <- turnLeft; .random(R); W = R * 10000 / 2; .wait(W); forward; .wait(1000).
+!move(N) : N < 1 & N > 0.75 <- turnRight; .random(R); W = R * 10000 / 2; .wait(W); forward; .wait(1000).
-!move(_) <- println("move failed").
