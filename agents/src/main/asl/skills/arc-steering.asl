// Skill: turns in arcs on the way, not in the thesis (tidy-up's). Heading (heading.asl) stops and turns
// on the spot at every re-alignment, the last 15 degrees slowly; along a route (route.asl) whose aim
// moves at every plan, and on the sweep's 2 s steps, a trip or a search turned on the spot every few
// seconds. Here a re-alignment of less than arcUpTo degrees is an arc: the outer wheel at travel speed,
// the inner slower by arcGain a degree, for as long as the turn takes (1.85 speed units a degree a
// second: the Khepera's 5.3 cm axle). With it: an obstacle met on a trip is gone round through the
// map (the route has it at once: back off a little and head for the route's next point; heading's
// detour, turn away, 1-5 s on at half speed and turn back, only when met again within detourNear),
// no steering in the middle of a detour, and no lateral reach for the stored pile.
// Parameters:
arcUpTo(50). arcGain(4).   // degrees; speed units a degree
arcTolerance(8).           // degrees off before a re-alignment on the way (heading: 10, 25 on a bend)
detourNear(0.1).           // m
pileNear(0.5). pileAngle(35).  // m, degrees: the stored pile this near, within the camera's view
// Reads: routePlanning, nearTarget (route); detours(N), headingOff, desiredOnTheRight, speedOnTheWay,
// steerNow (heading); travelling, halted, nearStorage, insideArea, stored(N) (delivery); searching
// (sweep). Beliefs: detouredAt(X, Z).
// Needs: route, heading (!computeGap, !balance). Include it after route, before delivery (its plans
// for !detour, !realign, !steer and !balance come before heading's) and before picking.

// the detour through the map (heading's @detour when met again near the last one)
againNear :- detouredAt(Dx, Dz) & location(X, _, Z) & detourNear(R) & (X - Dx) * (X - Dx) + (Z - Dz) * (Z - Dz) < R * R.
@detourOnRoute
+!detour(_) : routePlanning & not againNear & detours(N) & location(X, _, Z)
    <- +avoiding; stop; backward; .wait(200); stop; -+detours(N + 1); -+detouredAt(X, Z); -avoiding;
       !computeGap; !balance.

// on the way: within routeNear of the target point heading's turn on the spot (the storage point needs it)
offBy(A) :- travelling & not .intend(detour(_)) & arcTolerance(A).
@realignArc
+!realign : not .intend(detour(_)) & headingOff(G) & arcUpTo(U) & G < U & arcGain(K) & speedOnTheWay(V) & not (targetPoint(Tx, Tz) & nearTarget(Tx, Tz))
    <- Dv = math.min(V, K * G); W = math.round(1850 * G / Dv);
       if (desiredOnTheRight) { setSpeeds(V, V - Dv) } else { setSpeeds(V - Dv, V) }; .wait(W);
       if (not avoiding & not .intend(balance) & not .intend(detour(_)) & travelling & not halted) { setSpeeds(V, V) }.
// no re-alignment while a detour goes on: heading's steering turned the robot back to its aim in the
// middle of the detour's forward, into the box again, and the two took turns for 10 s and more
@steerAfterDetour +!steer : travelling & not halted & .intend(detour(_)) & steerNow(T) <- .wait(T); !steer.

// the sweep's turn towards its waypoint (each 2 s step re-aligns) is an arc too while searching, away
// from the storage area: 35-40 % of a search's time was turning on the spot. The end of it as
// heading's @balanced (no ~around, firstTime for the next entry)
@balanceArcSearching
+!balance : searching & not travelling & not nearStorage & not insideArea & headingOff(G) & G > 2 & arcUpTo(U) & G < U
            & arcGain(K) & speedOnTheWay(V)
    <- Dv = math.min(V, K * G); W = math.round(1850 * G / Dv);
       if (desiredOnTheRight) { setSpeeds(V, V - Dv) } else { setSpeeds(V - Dv, V) }; .wait(W); -~around; +firstTime.

// the stored pile at the side of the camera's image, near: no lateral reach for it (it turned the
// robot to the pile, the storage area's noAccess sent it away and skipped its waypoint, and the reach
// waited 5 s for nothing: 1-3 times a run, world 197 ten times in 150 s)
pileInSight :- stored(N) & N > 0 & location(X, _, Z) & orientation(O) & storagePoint(Sx, Sz) & pileNear(R) & pileAngle(A)
    & Dx = Sx - X & Dz = Sz - Z & D = math.sqrt(Dx * Dx + Dz * Dz) & D < R & H = O * math.pi / 180
    & Dx * math.cos(H) + Dz * math.sin(H) > D * math.cos(A * math.pi / 180).
@pileOnTheLeft +cylinderLeft : pileInSight.
@pileOnTheRight +cylinderRight : pileInSight.
