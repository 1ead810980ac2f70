// Skill: sweep search, not in the thesis. After searchAfter ms without a cylinder the random walk
// gives way to a sweep of the arena: lanes sweepSpacing apart, at sweepSpacing/2 from the walls,
// never into the storage area, with a look around (a full turn on the spot) at each waypoint and
// every lookEvery ms. A waypoint not reached in time is skipped.
// Parameters:
searchAfter(45000).   // ms without a cylinder before the sweep
// an agent's own searchDelay(Ms) rule or belief replaces it while it holds (team-search: a team's
// shared search starts sooner)
sweepDelay(S) :- searchDelay(S).
sweepDelay(S) :- not searchDelay(_) & searchAfter(S).
// lanes this far apart (m): the camera sees a cylinder up to about 1.5 m ahead within 30 degrees
// either side, so wider lanes leave no floor unseen, and the battery (1000 J, about 17 m of travel
// at full speed) no longer runs out on a third of a big arena (generated worlds: navigation
// 29 -> 36 of 50)
sweepSpacing(0.5).
sweepSpeed(100).
// ms between looks around: the camera sees a cylinder up to 1.5 m away but only 30 degrees either
// side, and a lane passed cylinders just out of its sight for minutes (generated worlds:
// navigation 129 -> 139 of 150, held out 119 -> 134; suspend/resume 131 -> 139, 123 -> 139)
lookEvery(25000).
// ms after an avoidance during which a step first drives straight on, so that heading for its point
// does not turn the robot straight back to what it avoided (team-storage's clear-out reads it too)
driveOnAfterAvoid(3000).
justAvoided(T) :- lastAvoid(A) & driveOnAfterAvoid(W) & T - A < W.
// A waypoint is skipped once the robot has come no closer to it by waypointProgress m for
// waypointPatience ms (a fixed 60 s per waypoint left the robot half a minute among boxes in front
// of a waypoint it could not reach, as in gradle run's story; generated worlds, suspend/resume:
// 128 -> 131 of 150, held out 123 -> 123). An agent's own waypointPatience(Ms) and
// waypointProgress(M | off) beliefs replace these defaults (off: a fixed time per waypoint).
patience(P) :- waypointPatience(P).
patience(20000) :- not waypointPatience(_).
progressStep(G) :- waypointProgress(G).
progressStep(0.1) :- not waypointProgress(_).
// no waypoint lies this near the storage point (m): its clearance (delivery) and 0.1 m more; in a
// world without a storage area (object picking) every waypoint is kept
laneClearance(L) :- storageClearance(C) & L = C + 0.1.
offStorage(X, Z) :- storagePoint(Sx, Sz) & laneClearance(C) & (X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz) > C * C.
offStorage(_, _) :- not storagePoint(_, _).
setUpGoal(setUpSweep).
// Reads: arena(W, D), storagePoint(X, Z) (the world's, optional: object picking has none); storageClearance(C), travelling (delivery);
// searchDelay(Ms) (the agent's, optional: see searchAfter); sweepFrom(Fx, Fz) (an agent's, optional:
// the corner the lanes begin at, see sweepCorner);
// lastAvoid(T) (avoidance); maxSpeed(M).
// Beliefs: searching, lastFound(T), lastLook(T), sweep(Waypoints), waypoint(X, Z, Since), closest(D),
// closerAt(T) (when the robot last came nearer its waypoint: way-round reads it),
// lookFirst (set by +fallen: a cylinder knocked out of the gripper lies beside the robot);
// resumeSweep (the agent's, optional: a new search goes on where the last one stopped).
// Rules it offers: laneClearance(L) (storage-bypass keeps the way to a waypoint as far from the storage point).
// Needs: !balance, !aimAt (heading, delivery's or the agent's own include; route.asl's way round what was met), !escape (recovery). Include it after recovery, before random walk.

@setUpSweep +!setUpSweep <- .system_time(Now); +lastFound(Now); +lastLook(Now); !!searchClock.

@moveLookFirst +!move(N) : lookFirst <- -lookFirst; !lookAround.
@moveSweeping +!move(N) : searching <- !sweepStep.

// a cylinder picked: the random walk or the sweep has done its job (its waypoint is no target now)
@found +!found <- .system_time(T); -+lastFound(T); -searching; .abolish(waypoint(_, _, _)).

@searchClock
+!searchClock : sweepDelay(S) & lastFound(T0)
    <- .wait(5000); .system_time(T);
       if (T - T0 > S & not searching & not travelling) { println("No cylinder for a while: sweeping the arena"); +searching; !planSweep };
       !searchClock.

// an agent that believes resumeSweep goes on along the lanes it had not yet driven
@planSweepResumed +!planSweep : resumeSweep & sweep([_ | _]) <- !nextWaypoint.
// the lanes begin at the corner (Fx, Fz) gives: -Fx * W / 2, -Fz * D / 2; an agent's own
// sweepFrom(Fx, Fz) rule replaces the default (search-memory: the corner nearest the robot)
sweepCorner(Fx, Fz) :- sweepFrom(Fx, Fz).
sweepCorner(1, 1) :- not sweepFrom(_, _).
// the waypoints of lanes 0..N, Step apart (signed: from the corner's side), each lane's ends at
// -Hx and Hx in turn, none into the storage area
sweepPoints(Hx, Hz, N, Step, Ws)
    :- .findall(lane(I, Z), .range(I, 0, N) & Z = -Hz + I * Step, Lanes) &
       .findall([X1, Z1], .member(lane(I1, Z1), Lanes) & ((I1 mod 2 == 0 & (X1 = -Hx | X1 = Hx)) | (I1 mod 2 == 1 & (X1 = Hx | X1 = -Hx))), All) &
       .findall([X2, Z2], .member([X2, Z2], All) & offStorage(X2, Z2), Ws).
// An arena under two spacings deep has one lane, and with one end by the storage area one
// waypoint: when a box stands on it the robot went back to it after every escape (a 0.96 m tidy-up
// arena, 350 s by one box): such an arena gets two lanes, sweepSpacing / 2 from either wall.
@planSweep
+!planSweep : arena(W, D) & sweepSpacing(S) & sweepCorner(Fx, Fz)
    <- Hx = Fx * (W / 2 - S / 2); Hz = Fz * (D / 2 - S / 2); N = math.floor(2 * Fz * Hz / S);
       ?sweepPoints(Hx, Hz, N, Fz * S, Lanes);
       if (.length(Lanes) < 2) { ?sweepPoints(Hx, Hz, 1, 2 * Hz, Ws) } else { Ws = Lanes };
       -+sweep(Ws); !nextWaypoint.

@nextWaypoint
+!nextWaypoint : sweep([[X, Z] | Rest])
    <- .concat(Rest, [[X, Z]], L); -+sweep(L); .system_time(T); -+waypoint(X, Z, T); -+closest(1000); -+closerAt(T).
@noWaypoint +!nextWaypoint.

// one step towards the waypoint: align, go 2 s
@waypointReached
+!sweepStep : waypoint(X, Z, T0) & location(Lx, _, Lz) & (X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz) < 0.01
    <- !nextWaypoint; !lookAround.
// a full turn on the spot, slowly enough for the camera's sightings: far sight takes any
// cylinder it shows (a sighting ends the move, and this turn with it)
@lookAround +!lookAround : maxSpeed(M) <- .system_time(T); -+lastLook(T); setSpeeds(-M / 2, M / 2); .wait(6800); stop.
@lookEvery +!sweepStep : lookEvery(L) & lastLook(T0) & .system_time(T) & T - T0 > L <- !lookAround.
@waypointSkipped
+!sweepStep : waypoint(X, Z, T0) & .system_time(T) & patience(P) & T - T0 > P
    <- !nextWaypoint.
// closest(D) and closerAt(T): the nearest the robot has come to its waypoint, and when it came
// progressStep nearer (0.1 m when off); the waypoint's own time is the progress's only when on
@towardsWaypoint
+!sweepStep : waypoint(X, Z, _) & location(Lx, _, Lz) & sweepSpeed(V) & closest(B)
    <- .system_time(T); Dist = math.sqrt((X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz));
       if (progressStep(G) & .number(G)) { Step = G } else { Step = 0.1 };
       if (Dist < B - Step) {
           -+closest(Dist); -+closerAt(T);
           if (progressStep(G2) & .number(G2)) { -+waypoint(X, Z, T) }
       };
       if (justAvoided(T)) { forward; .wait(1500) };
       ?location(Lx2, _, Lz2); !aimAt(X, Z); ?aim(Ax, Az); computeAngle(Lx2, Lz2, Ax, Az, D); -+desired(D); !balance;
       setSpeeds(V, V); .wait(2000).
@noSweepStep +!sweepStep <- !nextWaypoint; .wait(100).

// stuck (the middleware's progress percept) while searching: escape, and on to the next waypoint
@stuckEscape
+stuck : not avoiding
    <- println("No progress: escaping"); +avoiding; .succeed_goal(move(_)); stop; !escape; -avoiding; !nextWaypoint.
@stuckAvoiding +stuck.
