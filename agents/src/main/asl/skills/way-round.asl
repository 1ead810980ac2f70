// Skill: the way round a wall, not in the thesis: a "bug" boundary following (Lumelsky and
// Stepanov's Bug algorithms). On the way to a target point (delivery, the recharge trip: while
// "travelling") heading.asl goes round an obstacle and re-aligns with the target; against a wall
// across the arena that sent the robot back and forth in front of the wall. Here an obstacle met
// again near where one was met before on this trip is a wall between the robot and its target:
// the robot follows its boundary, the wall kept on one side by the front-left and front-right
// distance sensors, until the target lies on its free side (the leave condition), and heads for
// it again. Round a wall's end the boundary leads through a doorway or a corridor, so the robot
// finds the way without a map of the walls; a wall that ends at the arena's boundary is followed
// the other way. On the sweep's way to its waypoints a wall is followed only when the robot has
// come no nearer its waypoint for stallTime (a wall across the arena, the waypoint in the next
// room): following every box met twice there too lost runs that the sweep's own avoidance wins
// (wide generated worlds 51 and 53, tidy-up).
// Parameters:
rehitRadius(0.35).    // m: an obstacle met within this of an earlier one on this trip is a wall
followSpeed(70).      // wheel speed along the wall
followEvery(80).      // ms between two corrections of the heading along the wall
followLimit(150000).  // ms of following before it is given up (the other side is tried next)
minFollow(2500).      // ms of following before the leave condition is tested
leaveAngle(35).       // degrees: the target this far to the free side ends the following
leaveNear(0.15).      // m: no following this near the target (the last approach is heading's)
stallTime(20000).     // ms the sweep may come no nearer its waypoint before the wall is followed
sweepFollowLimit(60000). // ms of following towards a sweep's waypoint before it is skipped
sweepFollows(2).      // followings towards one waypoint at most (the second on the other side)
wallNear(200).        // a front sensor's reading over this: something near ahead (under it: that side is free)
// a fall drops every desire (delivery's @fallCylinder): a following it cut short is forgotten with them,
// else every obstacle met after it was taken for the wall (@obstacleWhileFollowing) and not avoided
forgetOnFall(followingWall(_, _, _)). forgetOnFall(followTarget(_, _)).
// turnToWall (the agent's, optional: see @wallOnOtherSide).
// rehitsToFollow(N) (the agent's, optional: obstacles met near here on this trip before a following
// begins; 1 without it).
// followLooped (a rule of another skill, optional: look-points.asl's; a following it holds for is
// given up as one that found no way round).
// Reads: targetPoint(X, Z), travelling, insideArea, delivering, nearStorage (heading, delivery,
// recharge-trip); detours(N) (heading: the count of obstacles met on this trip, reset to 0 when a
// trip starts); picking, reachCylinder(B) (picking); searching, waypoint(X, Z, T), closerAt(T)
// (sweep); location, orientation, leftSensor, rightSensor (the front-left and front-right
// sensors), centralSensor, obstacle(B), delta(D); arena(W, D); maxSpeed(M).
// Beliefs: hitPoint(X, Z) (where obstacles were met on this trip), followingWall(Side, Since, Dist)
// (the wall on Side, "left" or "right", since Since, Dist from the target when it began),
// gaveUpSide(Side), wedgedAlong (wedged once on this following), avoiding (avoidance: the other skills stand aside meanwhile), followTarget(X, Z)
// (the sweep's waypoint followed towards), followedTowards(X, Z, N, Side) (followings towards it).
// An agent with route.asl (routePlanning) plans its way round what it met instead: no following;
// one with way-back.asl goes back the way it came when its trail knows one (the hook !wallMet).
// Needs: !computeGap, !balance, !detour (heading), !nextWaypoint (sweep). Include it after recharge, before
// delivery (its obstacle and stuck plans come before heading's) and before sweep (its +!sweepStep
// plan comes first).

// the free run (m) from the robot to the arena's boundary along heading H (degrees, as computeAngle)
runTo(C, P, Half, T) :- C > 0.001 & T = (Half - P) / C.
runTo(C, P, Half, T) :- C < -0.001 & T = (-Half - P) / C.
runTo(C, _, _, 1000) :- C >= -0.001 & C <= 0.001.
freeRun(H, L) :- location(X, _, Z) & arena(W, D) & R = H * math.pi / 180 & Cx = math.cos(R) & Cz = math.sin(R)
    & runTo(Cx, X, W / 2, Tx) & runTo(Cz, Z, D / 2, Tz) & L = math.min(Tx, Tz).
// an obstacle met again near where an earlier one was met on this trip; an agent that believes
// rehitsToFollow(N) follows only once N obstacles were met near here on this trip (in an open
// arena among boxes, tidy-up: a single box met twice is gone round by a detour in 5 s, where the
// following went round it in 15-25 s, up to 65 s of a trip)
nearHit(Hx, Hz) :- location(X, _, Z) & rehitRadius(R) & hitPoint(Hx, Hz) & (X - Hx) * (X - Hx) + (Z - Hz) * (Z - Hz) < R * R.
metHereBefore :- not rehitsToFollow(_) & nearHit(_, _).
metHereBefore :- rehitsToFollow(N) & .count(nearHit(_, _), C) & C >= N.
atBoundary :- location(X, _, Z) & arena(W, D) & (math.abs(X) > W / 2 - 0.1 | math.abs(Z) > D / 2 - 0.1).
// where the robot is going: the target point of a trip (the sweep's way to its waypoints is left
// to avoidance: following the boxes met again while sweeping measured worse, see the header)
goingTo(X, Z) :- travelling & targetPoint(X, Z).
goingTo(X, Z) :- not travelling & searching & followTarget(X, Z).
// the sweep has come no nearer its waypoint for stallTime, and has not followed towards it enough
sweepStalled(X, Z) :- searching & not travelling & waypoint(X, Z, _) & closerAt(T0) & .system_time(T)
    & stallTime(S) & T - T0 > S & not (followedTowards(X, Z, N, _) & sweepFollows(M) & N >= M).
// ms of following before it is given up: a trip's, or the sweep's
followLimitNow(L) :- travelling & followLimit(L).
followLimitNow(L) :- not travelling & sweepFollowLimit(L).
// the following ends when another skill takes the wheels (a cylinder to pick, the storage area)
// or the robot is halted (heading's rule: at the charger, another agent's wheels)
followingOff :- picking | reachCylinder(true) | (nearStorage & not delivering) | halted.
targetDistance(Dist) :- location(X, _, Z) & goingTo(Tx, Tz) & Dist = math.sqrt((X - Tx) * (X - Tx) + (Z - Tz) * (Z - Tz)).

/* Where obstacles were met on this trip (heading counts them: detours) */

@newTrip +detours(0) <- .abolish(hitPoint(_, _)); .abolish(gaveUpSide(_)); !tripBegun.
// the hook for a skill that keeps something per trip (way-back.asl)
@tripBegunHere +!tripBegun.
@noteHit +detours(N) : N > 0 & location(X, _, Z) <- +hitPoint(X, Z).

/* A wall met again: follow it */

@followOnRehit[atomic]
+obstacle(true) : not routePlanning & goingTo(_, _) & not insideArea & not followingWall(_, _, _) & not followingOff & metHereBefore
                & targetDistance(Dist) & leaveNear(Near) & Dist > Near
    <- .drop_intention(balance); .drop_intention(detour(_)); !wallMet(Dist).
// the hook a skill that knows a way round supplies first (way-back.asl): here, the following
@followTheWall +!wallMet(Dist) <- !startFollowing(Dist, _).
@startFollowing
+!startFollowing(Dist, S)
    <- +avoiding; -wedgedAlong; stop; !chooseSide(S); .system_time(T); +followingWall(S, T, Dist);
       println("A wall between the robot and its target: following it, the wall on the ", S);
       !!followWall.

/* The sweep no nearer its waypoint: the next obstacle met is a wall to follow towards it */

// met head on, as on a trip (a following begun mid-turn left at once: the waypoint lay on the
// free side); the second following towards one waypoint takes the other side
@followOnStall[atomic]
+obstacle(true) : not routePlanning & sweepStalled(X, Z) & not avoiding & not followingWall(_, _, _) & not followingOff & not insideArea
                & location(Lx, _, Lz) & leaveNear(Near) & math.sqrt((X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz)) > Near
    <- .succeed_goal(move(_)); Dist = math.sqrt((X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz)); .abolish(gaveUpSide(_));
       if (followedTowards(X, Z, N, Side)) { -followedTowards(X, Z, N, Side); +gaveUpSide(Side); N2 = N + 1 } else { N2 = 1 };
       +followTarget(X, Z); !startFollowing(Dist, S); +followedTowards(X, Z, N2, S).
// meanwhile the sensors are the following's: no detour, no avoidance
@obstacleWhileFollowing +obstacle(true) : followingWall(_, _, _).

// the side with the longer run along the wall before the arena's boundary (a doorway is likelier
// there), unless that side was given up on this trip
@chooseSide
+!chooseSide(S) : location(X, _, Z) & goingTo(Tx, Tz)
    <- computeAngle(X, Z, Tx, Tz, D); ?freeRun(D - 90, L); ?freeRun(D + 90, R);
       if (L >= R) { S0 = right } else { S0 = left };
       if (gaveUpSide(S0) & not (gaveUpSide(right) & gaveUpSide(left))) { !otherSide(S0, S) } else { S = S0 }.
@otherSideLeft +!otherSide(right, left).
@otherSideRight +!otherSide(left, right).

/* Along the wall, one correction every followEvery ms */

// the target's bearing from the heading (Rel, -180..180, positive to the right: the compass turns
// clockwise) decides whether to leave the wall
@followWall
+!followWall : followingWall(S, T0, Dist0) & not followingOff & location(X, _, Z) & goingTo(Tx, Tz) & orientation(O)
    <- computeAngle(X, Z, Tx, Tz, D); R0 = D - O; Rel = R0 - 360 * math.round(R0 / 360);
       !followOrLeave(S, T0, Dist0, Rel).
@followEnded +!followWall <- !endFollowing.
@followDropped -!followWall <- !endFollowing.

@leaveWall
+!followOrLeave(S, T0, Dist0, Rel) : .system_time(T) & minFollow(Min) & T - T0 > Min & canLeave(S, Dist0, Rel)
    <- println("The target is on the free side: heading for it again"); !endFollowing; !headAgain(left).
// a skill's rule followLooped (look-points.asl's: round a box and back where the following began)
// gives the following up as one that found no way round
@followLooped
+!followOrLeave(S, _, _, _) : followLooped
    <- println("Round an obstacle and back: heading for the target again"); +gaveUpSide(S);
       !endFollowing; !headAgain(gaveUp).
@followGivenUp
+!followOrLeave(S, T0, _, _) : .system_time(T) & followLimitNow(Lim) & T - T0 > Lim
    <- println("No way round found on the ", S, ": heading for the target again"); +gaveUpSide(S);
       !endFollowing; !headAgain(gaveUp).
// the wall led to the arena's boundary, away from the target: no doorway that way; the other
// side, along the same wall (Bug would go round the whole room first)
@turnBackAtBoundary
+!followOrLeave(S, T0, Dist0, Rel) : .system_time(T) & minFollow(Min) & T - T0 > Min & atBoundary
                                    & math.abs(Rel) > 135 & not gaveUpSide(S)
    <- println("The wall ends at the arena's boundary: following it the other way"); +gaveUpSide(S);
       !otherSide(S, S2); -followingWall(S, T0, Dist0); +followingWall(S2, T, Dist0); !followWall.
@followStep +!followOrLeave(S, _, _, _) : followEvery(E) <- !alongWall(S); .wait(E); !followWall.

@endFollowing +!endFollowing <- .abolish(followingWall(_, _, _)); .abolish(followTarget(_, _)); -avoiding.
// the trip turns to its target again (heading); the sweep heads for its waypoint again, its clock
// started again, or skips it when no way round was found
@headAgainOnTrip +!headAgain(_) : travelling <- !computeGap; !balance; !wallStillAhead.
// the obstacle seen at the following's end raises no new event (the following took them all): a
// trip that turned to its target with the wall still ahead drove into it at full speed, sliding
// along it for 25 s (wide world 112, seed 1); it goes round it as round any obstacle met
@wallStillAhead +!wallStillAhead : travelling & obstacle(true) & not insideArea & delta(D) <- !detour(D).
@wallNotAhead +!wallStillAhead.
@waypointGivenUp +!headAgain(gaveUp) : searching <- !nextWaypoint.
@waypointAgain
+!headAgain(left) : searching & waypoint(X, Z, _) <- .system_time(T); -+waypoint(X, Z, T); -+closest(1000); -+closerAt(T).
@headAgainEnded +!headAgain(_).

// leave when the target is well to the free side, neither ahead (a corridor's far wall may be in
// the way) nor behind (its bearing there flips between -180 and 180)
canLeave(right, _, Rel) :- leaveAngle(A) & Rel < -A & Rel > A - 180 & leftSensor(F) & wallNear(L) & F < L.
canLeave(left, _, Rel) :- leaveAngle(A) & Rel > A & Rel < 180 - A & rightSensor(F) & wallNear(L) & F < L.

// the sensor on the wall's side (N) keeps the wall at 2-4 cm; the other (F) sees what comes ahead
@alongRight +!alongWall(right) : leftSensor(F) & rightSensor(N) <- !steerAlong(N, F, 1).
@alongLeft +!alongWall(left) : leftSensor(N) & rightSensor(F) <- !steerAlong(N, F, -1).
// Sign 1: the wall on the right (turning away is to the left)
// a box straight ahead, between the two sensors' beams, is seen by the central sensor alone (the
// middleware raises no obstacle from it while a cylinder is held): the robot turned and arced into
// it in turn, pressed against it for 40 s (wide world 114, seed 1)
@wallAhead +!steerAlong(N, F, Sign) : wallNear(L) & (F > L | N > 480 | (centralSensor(C) & C > L)) & maxSpeed(M) <- !wheels(-M / 4, M / 4, Sign).
// an agent that believes turnToWall: a following begun with the wall seen by the other front sensor
// alone (the sweep slid along it and turned towards its waypoint) turns on the spot while the wall
// is not yet on the side chosen (the arc for a wall lost circled on the spot until the loop check)
@wallOnOtherSide
+!steerAlong(N, F, Sign) : turnToWall & N < 60 & F > 60 & followingWall(_, T0, _) & .system_time(T) & minFollow(Min) & T - T0 < Min
                           & maxSpeed(M)
    <- !wheels(-M / 4, M / 4, Sign).
@tooClose +!steerAlong(N, F, Sign) : N > 300 & followSpeed(V) <- !wheels(V / 2, V, Sign).
@alongside +!steerAlong(N, F, Sign) : N > 60 & followSpeed(V) <- !wheels(V, V * 0.85, Sign).
@wallLost +!steerAlong(N, F, Sign) : followSpeed(V) <- !wheels(V, V * 0.3, Sign).
// the speeds for the wall on the right; mirrored for the wall on the left
@wheelsRight +!wheels(A, B, 1) <- setSpeeds(A, B).
@wheelsLeft +!wheels(A, B, -1) <- setSpeeds(B, A).

// wedged along the wall a second time: boxes, not a wall (a corner among boxes wedged the robot
// every 14 s until followLimit, 150 s of a tidy-up delivery): the following is given up
@stuckFollowingAgain
+stuck : followingWall(S, _, _) & wedgedAlong & maxSpeed(M)
    <- println("Wedged along the wall again: giving the following up"); .drop_intention(followWall);
       setSpeeds(-M / 2, -M / 2); .wait(800); +gaveUpSide(S); !endFollowing; !headAgain(gaveUp).
// wedged along the wall (the held cylinder against a corner): back off, turn away, go on
@stuckFollowing
+stuck : followingWall(S, _, _) & maxSpeed(M)
    <- println("No progress along the wall: backing off"); .drop_intention(followWall); +wedgedAlong;
       setSpeeds(-M / 2, -M / 2); .wait(800);
       if (S == right) { setSpeeds(-M / 4, M / 4) } else { setSpeeds(M / 4, -M / 4) }; .wait(600);
       if (followingWall(_, _, _)) { !!followWall }.
