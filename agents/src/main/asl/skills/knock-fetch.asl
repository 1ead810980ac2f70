// Skill: a cylinder knocked out of the gripper is turned to and fetched, not in the thesis. Once the
// robot knows a cylinder fell beside it (knockedAt(T): delivery's fall plan notes a fall by the
// storage area, knocked-aside.asl every knock beside the robot), the first distance sensor that
// shows it within knockedAside ms says on which side: the robot turns on the spot towards it until
// picking's reach takes it (avoidance turned the robot away from it, again and again, and the sweep
// drove off: tidy-up world 204 × 2, found again 138 s later). A cylinder knocked out by the storage
// area lies within delivery's storage clearance, where no cylinder is picked and the camera signals
// none (tidy-up world 174, 0.08 m from the storage point; navigation's wide world 111, seed 1, 0.075 m
// from it as the robot entered the area: never picked again, one delivery of two): for knockFetch ms
// after such a fall picking is allowed there.
// Parameters:
knockedAside(4500).   // ms after the knock that an obstacle met is taken for the cylinder
knockedTurn(14000).   // ms the turn lasts at most: a full turn at a quarter speed (the side sensed first
                      // may be a box's, world 183 × 2: the cylinder came round after three quarters)
knockFetch(20000).    // ms after a fall by the storage area that picking is allowed there (not in the thesis):
                      // the turn to it and picking's slow approach (a window of 10 s ended 0.2 s after the pick)
knockFetchWithin(0.08). // m beyond delivery's storage clearance that a fall counts as by the storage area
// Reads: knockedAt(T) (set by delivery's fall plan by the storage area, and by knocked-aside.asl); picking,
// reachCylinder (picking); maxSpeed(M); delta(D), location, orientation (the middleware's); gripPoint
// (gripper's, which picking includes: the gripper's point ahead of the robot); storagePoint(X, Z),
// storageRadius(R) (the world's); stored(N), storageWithin(M), gripToStorage(D2) (delivery).
// Beliefs: fellNearStorageAt(T) (delivery's fall plan); avoiding (avoidance's: every move, avoidance
// and far sight wait meanwhile).
// Rules it offers: fallenNearStorage, fetchingKnocked (delivery's pickingOff and recharge-trip read it).
// Needs: delivery, avoidance. Include it after delivery, before avoidance (its obstacle plans come after).
justKnocked :- knockedAt(T0) & knockedAside(A) & .system_time(T) & T - T0 < A & not avoiding & not picking & not reachCylinder(true).
// towards the side that shows it: the left sensor looks 90 degrees left, and a positive delta (left less right)
// is an obstacle ahead on the left; turnToKnocked(V) turns right for a positive V
@knockedLateral +lateralObstacle(S) : justKnocked & maxSpeed(M)
    <- if (S == "left") { !turnToKnocked(-M / 4) } else { !turnToKnocked(M / 4) }.
@knockedFront +obstacle(true) : justKnocked & maxSpeed(M) & delta(D)
    <- if (D > 0) { !turnToKnocked(-M / 4) } else { !turnToKnocked(M / 4) }.
@turnToKnocked
+!turnToKnocked(V) : knockedTurn(W)
    <- -knockedAt(_); +avoiding; .succeed_goal(move(_)); setSpeeds(V, -V); .wait(picking | reachCylinder(true), W); -avoiding.
// not seen in time: on with the search; seen meanwhile: picking's reach goes on
@turnToKnockedEnd -!turnToKnocked(_) : not picking & not reachCylinder(true) <- stop; -avoiding.
@turnToKnockedReach -!turnToKnocked(_) <- -avoiding.

// A cylinder knocked out by the storage area lies where no pick is allowed (delivery's nearStorage:
// tidy-up world 174, 0.08 m from the storage point, never picked again): for knockFetch ms after such
// a fall (delivery's fall plan notes it) picking is allowed there, so picking's reach takes it when the
// look around shows it in the camera's side section, and it is delivered at once.
fallenNearStorage :- knockFetchWithin(M) & storageWithin(M).
// Not from the pile: once a cylinder is stored, with the gripper's point within the storage radius of the
// storage point the cylinder there is a stored one (a quicker approach, tried: the fetch took one from the pile,
// standing 2.8 cm from the point, and delivered it again; the knocked one was left. With none stored, a robot
// facing the point as it fell, 11 cm away, still turns to the cylinder: world 174 × 2).
fetchingKnocked :- fellNearStorageAt(T0) & knockFetch(W) & .system_time(T) & T - T0 < W & not pileAhead.
pileAhead :- stored(N) & N > 0 & gripToStorage(D2) & storageRadius(R) & D2 < R * R.
