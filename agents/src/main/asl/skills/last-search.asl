// Skill: the search for the last cylinder, not in the thesis (tidy-up alone). With one cylinder left
// to store, the sweep's next waypoint is the nearest floor the camera has not yet looked over (the
// middleware's view map, kept all run while the camera scans: unseenNext), not its lanes' next end:
// the lanes' fixed round sent the last search back over floor searched before (world 190: 2 m across
// it after the third delivery, the far half never driven before 525 s). A point is done once the
// camera looked at it from within lastViewRange, or reached, or given up (the sweep's patience, an escape).
// Earlier searches keep the lanes: a map for every search lost (thirty-second session, 111 against 114).
// Parameters:
lastViewRange(0.9).   // m: floor looked at from this near counts as seen (boxes hide nothing on the map)
// Reads: stored(N) (delivery), cylinders(N), storagePoint(X, Z) (the world), picked (picking); searching,
// waypoint(X, Z, Since), laneClearance(L) (sweep); lookingAgain(X, Z, Since) (search-memory).
// Beliefs: viewCheckedAt(T) (when the waypoint was last checked against the view map).
// Needs: NavigationMiddleware's routeMap (route.asl), unseenNext, viewSeen. Include it after search-memory
// (a place where a cylinder was seen comes first) and before sweep (its plans come before the lanes').
lastCylinder :- stored(N) & cylinders(C) & N > C - 2 & N < C & not picked(true).

@lastUnseenNext
+!nextWaypoint : searching & lastCylinder & location(X, _, Z) & storagePoint(Sx, Sz) & laneClearance(L) & lastViewRange(R)
    <- unseenNext(X, Z, R, Sx, Sz, L, Px, Pz); .system_time(T); -+waypoint(Px, Pz, T); -+closest(1000); -+closerAt(T).
// at each sweep step (once: the step goes on through the sweep's plans), a waypoint the camera has looked
// at already gives way to the next unseen floor
@lastPointSeen
+!sweepStep : searching & lastCylinder & waypoint(Wx, Wz, _) & not lookingAgain(Wx, Wz, _) & lastViewRange(R)
              & .system_time(T) & not (viewCheckedAt(T0) & T - T0 < 500)
    <- -+viewCheckedAt(T); viewSeen(Wx, Wz, R, S); if (S == 1) { !nextWaypoint }; !sweepStep.
