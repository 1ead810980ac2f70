// Skill: heading by compass to a target point (thesis Chapter 4 §3.1), with the Khepera's GPS and
// compass: turn to the heading of the target point (computeGap, balance), go at travel speed,
// re-align on the way (steer), go round an obstacle met on the way (detour) and escape when the
// middleware says "stuck". Delivery heads for the storage point with it, recharge for the charger
// and back to the marked point.
// Parameters:
steerEvery(2500).   // ms between heading checks on the way
bendSteerEvery(1000). // ms between them while the way bends (route.asl, way-back.asl: aim is not the target)
bendTolerance(25).  // degrees off a way that bends before a re-alignment (10 otherwise)
detours(0).         // obstacles met on this trip: each detour goes round longer
quickTurnAt(50, 15). // with quickTurns (the agent's): wheel speed of a turn on the spot, and the last degrees turned slowly
// the wheel speed on the way: far sight's travelSpeed when the agent has it
speedOnTheWay(V) :- travelSpeed(V).
speedOnTheWay(100) :- not travelSpeed(_).
// Reads: targetPoint(X, Z) (the skill that sends the robot: delivery, recharge); location, orientation,
// delta (the middleware); travelling, halted, insideArea (rules of the skills that send the robot),
// avoiding (avoidance); quickTurns or quickTurn(V, A) (the agent's, optional: see @balanceQuickRight).
// An agent may put a rule offBy(A) of its own before its includes (the first that holds is taken: tidy-up's
// 3 degrees near the storage point).
// Beliefs: desired(Degrees), firstTime, ~around (delivery reads them), aim(X, Z) (the point headed
// for: the target point, or route.asl's point on the way to it).
// Needs: avoidance (!avoid), recovery (!escape). Included by delivery (between its "+stuck" plans:
// picking and the storage area come first); an agent without delivery includes it before avoidance.

/* Going round obstacles on the way: a detour, then re-align (Chapter 4 §3.1) */

// Recovery, not in the thesis: the detour is one goal (a newer obstacle replaces it) and goes
// round the obstacle longer each time (forward 1 s, then up to 4 s more); a lateral obstacle
// is gone round as a front one.
@detourObstacle
+obstacle(true) : travelling & delta(D) & not insideArea
    <- .drop_intention(balance); .drop_intention(detour(_)); !detour(D).
@detourLateral
+lateralObstacle(S) : travelling & not insideArea & not avoiding
    <- .drop_intention(balance); .drop_intention(detour(_)); if (S == "left") { !detour(-1) } else { !detour(1) }.
// forward before re-aligning: re-aligning at once turned the robot back into the obstacle it had
// just left, and it could dither for minutes in front of a box between it and the storage point
@detour
+!detour(D) : detours(N)
    <- +avoiding; stop; !avoid(D); -+detours(N + 1);
       .random(R); F = 1000 + R * 1000 * math.min(N, 4); forward; .wait(F);
       !computeGap; !balance.

/* Heading towards the target point with the compass (Chapter 4 §3.1) */

// the heading for the target point, or for the point on the way to it that route.asl gives
@computeGap
+!computeGap : location(X, Y, Z) & targetPoint(Tx, Tz)
    <- !aimAt(Tx, Tz); ?aim(Ax, Az); computeAngle(X, Z, Ax, Az, Desired); -+desired(Desired).
@aimStraight +!aimAt(Tx, Tz) <- -+aim(Tx, Tz).

@balanced
+!balance : desired(D) & orientation(O) & O > D - 0.6 & O < D + 0.6
    <- stop; -~around; +firstTime; !cruise.
// near 0/360 the window above never holds (e.g. D = 0.3, O = 359.9)
@balancedAcrossNorth
+!balance : desired(D) & orientation(O) & (O - D > 359.4 | D - O > 359.4)
    <- stop; -~around; +firstTime; !cruise.
// the shorter turn to the desired heading is a right (clockwise) one
desiredOnTheRight :- desired(D) & orientation(O) & ((O - D >= -180 & O - D < 0) | O - D >= 180).
// an agent that believes quickTurns (tidy-up, navigation) turns on the spot at
// wheel speed V while the heading is more than A degrees off (quickTurnAt(V, A)), and slowly only
// for the last A: the thesis' slow turn took 9 s for a half turn, 60-100 s of a ten-minute tidy-up
// run; an agent may believe quickTurn(V, A) itself instead
quickTurn(V, A) :- quickTurns & quickTurnAt(V, A).
// the straight distance (m) from the robot to (Tx, Tz): recharge-trip's and team-charger's
distanceTo(Tx, Tz, D) :- location(X, _, Z) & D = math.sqrt((X - Tx) * (X - Tx) + (Z - Tz) * (Z - Tz)).
headingOff(G) :- desired(D) & orientation(O) & R = math.abs(O - D) & G = math.min(R, 360 - R).
@balanceQuickRight
+!balance : quickTurn(V, A) & headingOff(G) & G > A & desiredOnTheRight
    <- setSpeeds(V, -V); .wait(20); !balance.
@balanceQuickLeft
+!balance : quickTurn(V, A) & headingOff(G) & G > A <- setSpeeds(-V, V); .wait(20); !balance.
@balanceRight
+!balance : desiredOnTheRight
    <- setSpeeds(25, -10); .wait(20); !balance.
@balanceLeft
+!balance : desired(D) & orientation(O) & ((O - D < 180 & O - D > 0) | O - D < -180)
    <- setSpeeds(-10, 25); .wait(20); !balance.
@balanceWait +!balance <- .wait(20); !balance.
// the balance plans end by going on at travelSpeed (the thesis: forward)
@cruise +!cruise : speedOnTheWay(V) <- setSpeeds(V, V).

// while travelling: re-align when the heading is off by more than 10 degrees (more often while
// the way to the target bends: route.asl)
bending :- aim(Ax, Az) & targetPoint(Tx, Tz) & (Ax \== Tx | Az \== Tz).
steerNow(T) :- bending & bendSteerEvery(T).
steerNow(T) :- steerEvery(T).
// degrees off before a re-alignment: more along a route that bends (its point on the way moves a
// cell to and fro at every plan, and each turn on the spot stopped the robot)
offBy(A) :- bending & bendTolerance(A).
offBy(10).
@steer
+!steer : travelling & not halted & steerNow(T)
    <- .wait(T);
       if (not avoiding & not .intend(balance) & not halted & travelling & location(X, _, Z) & targetPoint(Tx, Tz)) {
           !aimAt(Tx, Tz); ?aim(Ax, Az); computeAngle(X, Z, Ax, Az, D); ?orientation(O);
           ?offBy(A);
           if (math.abs(O - D) > A & math.abs(O - D) < 360 - A) { -+desired(D); !realign }
       };
       !steer.
@steerDone +!steer.
// along a route that bends (route.asl) the turn is an intention of its own, so that a detour that
// drops it (.drop_intention(balance)) does not end the steering too, as it does here otherwise
@realignOnRoute +!realign : bending <- !!balance.
@realign +!realign <- !balance.
@steerRetry -!steer <- .wait(500); !steer.

/* No progress though the wheels turn, on the way */

@stuckOnTheWay
+stuck : travelling & not avoiding
    <- println("No progress: escaping"); .drop_intention(balance); .drop_intention(detour(_));
       +avoiding; stop; !escape; -avoiding; .wait(800); !computeGap; !balance.
