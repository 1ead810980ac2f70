// Skill: a look at the storage area's rim, not in the thesis. Far sight takes no cylinder whose line
// passes the storage clearance (the middleware's ignoreCylindersNear, search-memory's towardsStored: the
// stored pile), the search remembers none near it (nearStored) and the sweep's waypoints keep off it
// (laneClearance), so a cylinder lying beside the storage area was never taken (a hand-made arena, one
// 14 cm from the storage point: 0 of 3 runs). Once the sweep has gone through all its waypoints since
// the last pick and a cylinder is still to store, the robot goes to points round the storage point,
// rimDistance away (towards the arena's centre and rimSpread either side, inside the arena), and from
// each drives slowly straight at the storage point: the camera and the central sensor (picking) take a
// cylinder met on the way; the middleware's noAccess ends the approach at the area's clearance.
// Parameters:
rimDistance(0.35).   // m from the storage point where each approach begins
rimSpread(45).       // degrees between the approach lines
rimApproach(12000).  // ms an approach lasts at most (0.2 m at half speed take about 8 s)
// Reads: storagePoint(X, Z), arena(W, D), cylinders(N) (the world's); stored(N), storageWithin(E) (delivery); searching,
// sweep(L), waypoint(X, Z, T) (sweep); location; maxSpeed(M).
// Beliefs: lanesFrom(P) (the sweep's next waypoint when the lanes went on after the last pick),
// rimPoints(L) (the approaches' starts still to drive to), rimStart(X, Z) (the one driven to now), rimLooked.
// Rules it offers: reachOff (picking: no lateral reach).
// Needs: sweep (its waypoint plans: include this before sweep, after search-memory), heading (!balance).

rimPoint(A, Sx, Sz, R, [X, Z]) :- X = Sx + R * math.cos(A * math.pi / 180) & Z = Sz + R * math.sin(A * math.pi / 180).
insideArena([X, Z]) :- arena(W, D) & math.abs(X) < W / 2 - 0.1 & math.abs(Z) < D / 2 - 0.1.
rimStarts(L) :- storagePoint(Sx, Sz) & rimDistance(R) & rimSpread(G) & C = math.atan2(-Sz, -Sx) * 180 / math.pi
    & .findall(P, .member(K, [0, -1, 1]) & rimPoint(C + K * G, Sx, Sz, R, P) & insideArena(P), L).
leftToStore :- cylinders(M) & stored(N) & N < M.
// during the look no lateral reach within 0.1 m of the storage clearance: the camera's side section shows
// the pile's cylinders there, and picking's reach turned the robot into the area ("Too close to storage
// area"), again after every escape (generated world 197: to the end of the run)
reachOff :- rimStart(_, _) & storageWithin(0.1).

// the lanes' cycle: the first waypoint ahead once the search went on, and its return to the head
@lanesBegun +sweep([P | _]) : searching & not lanesFrom(_) <- +lanesFrom(P).
@lanesDone
+sweep([P | _]) : searching & lanesFrom(P) & not rimLooked & leftToStore & rimStarts(L) & L = [_ | _]
    <- +rimLooked; -+rimPoints(L); println("The lanes gone through in vain: a look at the storage area's rim").
@lanesForgotten -searching <- .abolish(lanesFrom(_)); -rimLooked; .abolish(rimPoints(_)); .abolish(rimStart(_, _)).

@nextRimStart
+!nextWaypoint : searching & rimPoints([[X, Z] | Rest])
    <- -+rimPoints(Rest); -+rimStart(X, Z); .system_time(T); -+waypoint(X, Z, T); -+closest(1000); -+closerAt(T).
@rimDone +!nextWaypoint : searching & rimPoints([]) & rimStart(_, _) <- -rimPoints([]); -rimStart(_, _); !nextWaypoint.

// at an approach's start: straight at the storage point, slowly, until the robot is 1 cm short of the
// storage clearance (delivery's storageWithin; picking is off within it, and the middleware's noAccess
// sends the robot away) or the time is up; a pick on the way ends the move (picking)
@rimApproach
+!sweepStep : rimStart(X, Z) & waypoint(X, Z, _) & location(Lx, _, Lz) & (X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz) < 0.01
              & storagePoint(Sx, Sz) & maxSpeed(M)
    <- computeAngle(Lx, Lz, Sx, Sz, D); -+desired(D); !balance; setSpeeds(M / 2, M / 2); .system_time(T0); !approachRim(X, Z, T0).
@rimApproachEnded
+!approachRim(X, Z, T0) : rimStart(X, Z) & (storageWithin(0.01) | (.system_time(T) & rimApproach(A) & T - T0 > A))
    <- stop; !nextWaypoint.
@rimApproachOn +!approachRim(X, Z, T0) : rimStart(X, Z) <- .wait(200); !approachRim(X, Z, T0).
@rimApproachLeft +!approachRim(_, _, _).
