// Skill: far sight, not in the thesis. The thesis sees a cylinder only when it is near (the
// camera's three section means); the whole image shows one up to about 1.5 m away. The middleware
// signals cylinderSighted(Offset, Distance); the robot turns towards it and goes closer, steering
// (homing); picking takes it when it is near. A cylinder chased too long is given up and ignored
// a while; one lost from sight is not chased again at once.
// Parameters:
sightingEvery(400).     // ms between sightings
cameraFov(60).          // degrees
approachSpeed(40).      // wheel speed of the approach
farApproach(0.45).      // a cylinder this far (m) or more is approached at travelSpeed: at
                        // approachSpeed one 1.5 m away took over a minute
travelSpeed(100).       // wheel speed of travel (the thesis' forward is 50): big arenas
homingGiveUp(40000).    // ms one cylinder is chased
ignoreFor(15000).       // ms it is then ignored
lostSightIgnore(5000).  // ms a cylinder lost from sight is ignored: the sweep's turn towards its
                        // waypoint and the homing turn towards a cylinder at the edge of the
                        // image took turns for minutes
goRoundTime(2500).      // ms to go on past an obstacle met on the way (steering straight back
                        // drove into the same box until homingGiveUp)
setUpGoal(setUpFarSight).
// everyRedRun (the agent's, optional): every red run of the image is a sighting, widest first.
// Beliefs: homing(Since), lastSighted(T), sightDistance(D), ignoring, goingRound; nearestSighted(Since,
// D, At) (with homingProgress(Ms), the agent's, optional: a homing still coming nearer goes on past
// homingGiveUp while a sighting nearer than any before came in the last Ms).
// sightOffset(Off) (the last sighting's offset, for a skill that places it: search-memory).
// Reads: maxSpeed(M); picking, picked(true), reachCylinder(false), pickingOff (picking); avoiding;
// rule sightingOff(Off, Dist) (another skill's, optional: a sighting it takes for no cylinder to go
// for; search-memory: the stored pile).
// Needs: !escape (recovery). Include it after picking, before recovery.

// an agent that believes everyRedRun (tidy-up) is shown a cylinder beside the storage area's pile
// too: every red run of the image is looked at, not only the widest (the middleware's filter left
// out the pile's, and with it anything else in view)
@setUpFarSightEveryRun
+!setUpFarSight : everyRedRun & sightingEvery(E) & cameraFov(F) <- scanForCylinders(E, F); sightEveryRedRun.
@setUpFarSight +!setUpFarSight : sightingEvery(E) & cameraFov(F) <- scanForCylinders(E, F).

@homeOnSighting
+cylinderSighted(Off, Dist) : not picking & not picked(true) & not avoiding & reachCylinder(false) & not ignoring
                           & not goingRound & not pickingOff & not sightingOff(Off, Dist)
    <- !sighted(Off, Dist).
// what a sighting leads to: homing on it (a team's skill first claims the cylinder: team-claims)
@sightedHome +!sighted(Off, Dist) <- !homeOn(Off, Dist).
// the nearest this homing has seen its cylinder, and when (homingProgress)
@homeOnNearer
+!homeOn(Off, Dist) : homingProgress(_) & homing(T0) & not (nearestSighted(T0, N, _) & Dist >= N)
    <- .system_time(T); .abolish(nearestSighted(_, _, _)); +nearestSighted(T0, Dist, T);
       -+lastSighted(T); -+sightDistance(Dist); -+sightOffset(Off); !home(Off).
@homeOn +!homeOn(Off, Dist) <- .system_time(T); -+lastSighted(T); -+sightDistance(Dist); -+sightOffset(Off); !home(Off).

@homeStart +!home(Off) : not homing(_) <- .system_time(T); +homing(T); .succeed_goal(move(_)); !steerTo(Off).
// Recovery, not in the thesis: homingGiveUp ran out 9-15 cm from a cylinder approached at
// approachSpeed all the way; with homingProgress the homing goes on while it still comes nearer
@homeNearing
+!home(Off) : homingProgress(P) & homing(T0) & nearestSighted(T0, _, At) & .system_time(T) & T - At < P
    <- !steerTo(Off).
@homeGiveUp
+!home(_) : homing(T0) & homingGiveUp(G) & .system_time(T) & T - T0 > G & ignoreFor(I)
    <- println("The cylinder in sight cannot be reached: looking elsewhere");
       -homing(_); +ignoring; +avoiding; !escape; -avoiding; .wait(I); -ignoring.
@homeSteer +!home(Off) <- !steerTo(Off).

@goRound +!goRound : travelSpeed(V) & goRoundTime(T) <- +goingRound; setSpeeds(V, V); .wait(T); -goingRound.
@goRoundDropped -!goRound <- -goingRound.

// turn on the spot when it is well to a side, else steer towards it on the way
@steerRight +!steerTo(Off) : Off > 12 & maxSpeed(M) <- setSpeeds(M / 4, -M / 4).
@steerLeft +!steerTo(Off) : Off < -12 & maxSpeed(M) <- setSpeeds(-M / 4, M / 4).
@steerFar +!steerTo(Off) : sightDistance(D) & farApproach(F) & D >= F & travelSpeed(V) <- setSpeeds(V - 10 + Off, V - 10 - Off).
@steerNear +!steerTo(Off) : nearSpeed(V) <- setSpeeds(V + Off, V - Off).
// an agent may believe quickApproach(V): the near approach at V, not approachSpeed (tidy-up, whose runs end on time)
nearSpeed(V) :- quickApproach(V).
nearSpeed(V) :- not quickApproach(_) & approachSpeed(V).

// going to a cylinder seen far off, while it stays in sight
@moveWhileHoming +!move(N) : homing(_) & lastSighted(S) & .system_time(T) & T - S < 1500 <- .wait(300).
@moveLostSight +!move(N) : homing(_) <- -homing(_); !!lookAway.
@lookAway +!lookAway : lostSightIgnore(I) <- +ignoring; .wait(I); -ignoring.
