// Skill: no second look around where the camera has just looked, not in the thesis. Turning on the
// spot took 38-46 % of navigation's search (wide world 107, seed 1: 149 s of 390): a look point
// reached near where a full look around was made a little before (the last look point's, or the
// sweep's look every lookEvery ms) turned again over the same floor. The places of full looks
// around are kept; a look point within lookSkip's radius of one made within its time is left out
// of the round; reached anyway (the nearest, when every one left is such) it gets no turn while
// the round still holds a point not looked near, nor does the look every lookEvery ms there.
// Parameters (the agent's): lookSkip(R, F): R m, F ms; without it this skill does nothing.
// Reads: lookEvery(L), lastLook(T) (sweep); sweep(Points), waypoint(X, Z, T), lanesOnly, lookReach(R)
// (look-points); lookingAgain(X, Z, T) (search memory); location.
// Beliefs: lookedAt(X, Z, T) (where a full look around ended, and when).
// Needs: sweep (!lookAround), look-points. Include it after search memory and before look-points
// (its plans come before look-points' @nextLookPoint and @lookPointReached).

lookedNear(X, Z, T) :- lookSkip(R, F) & lookedAt(Lx, Lz, T0) & T - T0 < F & (X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz) < R * R.

// a full look around is recorded when it ends: one cut short by a sighting saw only part of the floor
@lookAroundKept +!lookAround : lookSkip(_, _) & not .intend(lookAroundWhole) <- !lookAroundWhole.
@lookAroundWhole
+!lookAroundWhole : lookSkip(_, F)
    <- !lookAround; ?location(X, _, Z); .system_time(T);
       for (lookedAt(Lx, Lz, T0) & T - T0 >= F) { -lookedAt(Lx, Lz, T0) };
       +lookedAt(X, Z, T).

// the look points near a recent look around leave the round, unless none would be left
@lookPointsSeen
+!nextWaypoint : lookSkip(_, _) & not lanesOnly & sweep(Ps) & .system_time(T) & .member([X0, Z0], Ps) & lookedNear(X0, Z0, T)
                 & .findall([X, Z], .member([X, Z], Ps) & not lookedNear(X, Z, T), Keep) & Keep = [_ | _]
    <- -+sweep(Keep); !nextWaypoint.

// (only while the round still holds a point not looked near: in an arena of one look point the round
// is planned again at once, and skipping it there ran the reasoning away)
@lookPointSeenReached
+!sweepStep : lookSkip(_, _) & waypoint(X, Z, _) & not lookingAgain(X, Z, _) & location(Lx, _, Lz) & lookReach(R)
              & (X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz) < R * R & .system_time(T) & lookedNear(X, Z, T)
              & sweep(Ps) & .member([X1, Z1], Ps) & not lookedNear(X1, Z1, T)
    <- !nextWaypoint.

// the sweep's look every lookEvery ms is put off where a full look around was made within the time
@lookEverySeen
+!sweepStep : lookSkip(_, _) & lookEvery(L) & lastLook(T0) & .system_time(T) & T - T0 > L & location(X, _, Z) & lookedNear(X, Z, T)
    <- -+lastLook(T); !sweepStep.
