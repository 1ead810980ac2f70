// Skill: the sweep by look points, not in the thesis. The sweep's lanes (sweep.asl) drive the whole
// arena sweepSpacing apart, wall to wall, again and again: in a 3 x 3 m arena one round is some 18 m,
// more than the battery's (1000 J, about 17 m), and after a delivery the lanes went on over floor the
// robot had just seen. Here the search heads for points on a grid lookSpacing apart (each at most
// lookSpacing / 2 * sqrt(2) from any floor, within the camera's 1.5 m) and turns on the spot at each
// (sweep's look around): the nearest point not yet visited in this round first, so the floor not
// seen lately comes before the floor seen; a round ends when every point was reached or skipped,
// and the next begins (a cylinder the world moved may lie where the robot looked before).
// Parameters (the agent's): lookSpacing(S), m; without it this skill does nothing.
lookReach(0.15).   // m: a look point this near is reached (its look around sees as far)
// a look point (a waypoint of the sweep) is skipped after 60 s, progress or not: sweep's progress
// -based skip measured worse for navigation (generated worlds 129 -> 119 of 150)
waypointPatience(60000).
waypointProgress(off).
// ms a place where a cylinder was seen is looked for again at most, then the look points go on (a
// boundary following towards it starts its waypoint's patience again: one place held the search
// 167 s of the 384 after the delivery, wide world 138 seed 1)
lookAgainFor(40000).
// ms after which a following towards a look point that is back within loopRadius (m) of where it
// began has gone round an obstacle, a box and no wall: no way round (way-round's @followLooped)
loopAfter(8000).
loopRadius(0.08).
// Optional (the agent's): lookNearing(G), ms: a look point whose patience (sweep's) has run out is
// kept while the robot came nearer it within the last G ms, up to lookPointMost ms in all (wide
// world 128, seed 1: 0.33 m from a point in a doorway when its 60 s ran out).
lookPointMost(120000).
// Reads: arena(W, D); location; offStorage(X, Z), searching (sweep); lookingAgain(X, Z, T) (search
// memory: its place looked for again is no look point); avoiding, picking, travelling, insideArea
// (avoidance, picking, delivery); stuck (the middleware's progress watch); followingWall(S, T, D)
// (way-round: a following towards the look point), wedgedAlong (way-round: wedged on it once).
// Beliefs: sweep(Points) (the look points left in this round), lookPointSet(X, Z, T) (when the look
// point became the waypoint), lanesOnly (no look point lies off the
// storage area: the sweep's lanes instead), lookAgainFrom(X, Z, T) (when the place looked for
// again became the waypoint), followFrom(X, Z, T) (where the following begun at T began).
// Rules it offers: followLooped (way-round gives such a following up).
// Needs: sweep (!lookAround, waypoint, closest, closerAt; its plans are the fall-back), !escape
// (recovery). Include it after search memory (its remembered cylinders come first) and before sweep.

// the grid: Nx by Nz points, the arena cut into equal cells at most lookSpacing a side, a point
// at the centre of each, none in the storage area
@planLookPoints
+!planSweep : lookSpacing(S) & not lanesOnly & not sweep([_ | _]) & arena(W, D)
    <- Nx = math.ceil(W / S); Nz = math.ceil(D / S);
       .findall([X, Z], .range(I, 0, Nx - 1) & .range(J, 0, Nz - 1) & X = -W / 2 + (I + 0.5) * W / Nx
                & Z = -D / 2 + (J + 0.5) * D / Nz & offStorage(X, Z), Ps);
       if (Ps == []) { +lanesOnly; !planSweep } else { -+sweep(Ps); !nextWaypoint }.

// the nearest look point left; with none left a new round
@nextLookPoint
+!nextWaypoint : lookSpacing(_) & not lanesOnly & sweep(Ps) & Ps = [_ | _] & location(Lx, _, Lz)
    <- .findall(d(D2, X, Z), .member([X, Z], Ps) & D2 = (X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz), Ds);
       .min(Ds, d(_, Wx, Wz)); .delete([Wx, Wz], Ps, Rest); -+sweep(Rest);
       .system_time(T); -+waypoint(Wx, Wz, T); -+lookPointSet(Wx, Wz, T); -+closest(1000); -+closerAt(T).
@newLookRound
+!nextWaypoint : lookSpacing(_) & not lanesOnly & sweep([]) <- -sweep([]); !planSweep.
// a search whose round is gone plans a new one: @newLookRound forgets the round's end and then plans the
// next, and a goal ended between the two (suspend/resume: after the way back from the charger) left
// neither; the sweep then stepped through no waypoint at all (classic world 15, seed 2: the reasoning
// ran away at 541 s)
@lookRoundLost +!nextWaypoint : searching & lookSpacing(_) & not lanesOnly & not sweep(_) <- !planSweep.

// a look point is reached within lookReach (a point among boxes was driven round for the waypoint's
// 0.1 m until its patience ran out)
@lookPointReached
+!sweepStep : lookSpacing(_) & waypoint(X, Z, _) & not lookingAgain(X, Z, _) & location(Lx, _, Lz) & lookReach(R)
              & (X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz) < R * R
    <- !nextWaypoint; !lookAround.

// the patience run out while the robot still comes nearer: the point's clock set so that it runs
// out lookNearing after the last approach (sweep's closerAt)
@lookPointNearing
+!sweepStep : lookNearing(G) & waypoint(X, Z, T0) & not lookingAgain(X, Z, _) & patience(P) & .system_time(T) & T - T0 > P
              & closerAt(C) & T - C < G & lookPointSet(X, Z, S) & lookPointMost(M) & T - S < M
    <- -+waypoint(X, Z, C + G - P); !sweepStep.

@lookAgainStarted +lookingAgain(X, Z, 0) : lookSpacing(_) <- .system_time(T); .abolish(lookAgainFrom(_, _, _)); +lookAgainFrom(X, Z, T).
@lookAgainTooLong
+!sweepStep : lookSpacing(_) & waypoint(X, Z, _) & lookingAgain(X, Z, _) & lookAgainFrom(X, Z, T0) & lookAgainFor(L)
              & .system_time(T) & T - T0 > L
    <- .abolish(lookingAgain(_, _, _)); println("Looked for too long where a cylinder was seen: on to the next"); !nextWaypoint.

// an avoidance cut off leaves "avoiding" behind: recovery's avoidance of an obstacle still seen runs
// inside the motion loop's move, and a lateral cylinder's reach ends that move before the avoidance
// takes "avoiding" back; every move then waits for it (wide world 241, seed 2: the robot stood still
// from 179 s to the end). No progress while no avoidance holds it: it goes, and the search goes on
@stuckAvoidingNone
+stuck : lookSpacing(_) & avoiding & not picking & not travelling & not insideArea
         & not .intend(avoid(_)) & not .intend(escape) & not .intend(leaveStorage)
    <- println("No progress, no avoidance under way: going on"); -avoiding; .succeed_goal(move(_)); stop; !escape; !nextWaypoint.

// where a following towards a look point began (wide world 136, seed 1: the robot circled three
// boxes among which its points lay, up to way-round's 60 s each, and its first pick came at 402 s);
// not after a wedge (way-round's backing off left the robot by its start: no loop)
@followBegun +followingWall(_, T, _) : lookSpacing(_) & not travelling & location(X, _, Z) <- -+followFrom(X, Z, T).
followLooped :- lookSpacing(_) & not travelling & not wedgedAlong & followingWall(_, T0, _) & followFrom(X0, Z0, T0) & .system_time(T)
    & loopAfter(A) & T - T0 > A & location(X, _, Z) & loopRadius(R) & (X - X0) * (X - X0) + (Z - Z0) * (Z - Z0) < R * R.
