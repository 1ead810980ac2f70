// Skill: the side of a wall to follow, taken from the robot's own trail; not in the thesis.
// way-round chooses the side with the longer free run before the arena's boundary, blind to where
// the doorway is: in wide worlds 112, 128 and 154 a delivery followed the wall to the boundary first
// and back (128, seed 2: 50 s there, 70 s back). The robot keeps a trail point every trailStep m driven;
// the most recent one beyond the wall met (past it by trailPast along the arena's axis nearest the
// way to the target: the worlds' walls run along the axes) is where the robot came from, through
// the wall's doorway or round its end, and the following goes that way. Without such a point, or
// with that side given up, way-round's own choice.
// Parameters (the agent's): trailStep(S), m; without it this skill does nothing.
trailPast(0.15).   // m beyond the robot, along the axis, for a trail point to lie past the wall
// m beyond the robot for a point laid while following a wall: a thin wall's far face lies some 0.1 m
// beyond its near face (the robot's centre 4-5 cm off either face), under trailPast, and the way the
// robot came through a doorway along that face did not count (wide worlds 349 and 351: an older point
// took the trip to the wall's other end); any point at 0.08 took a box's side from where the robot
// had been before it drove to the box (wide world 112)
trailPastAlong(0.08).
setUpGoal(setUpTrailSide).
// Reads: location, goingTo(X, Z), gaveUpSide(S), followingWall(S, T, D) (way-round).
// Beliefs: trail(N, X, Z) (the N-th point), trailLast(N, X, Z) (the last one), trailAlong(N, X, Z)
// (the N-th point, laid while following a wall).
// Needs: way-round (!chooseSide, !otherSide). Include it before way-round (its !chooseSide plan comes first).

@setUpTrailSide +!setUpTrailSide : trailStep(_) <- !!trailClock.
@setUpTrailSideOff +!setUpTrailSide.

// the first point half a second in: before the first GPS reading the location is (0, 0)
@trailFirst +!trailClock : not trailLast(_, _, _) & location(_, _, _) <- .wait(500); ?location(X, _, Z); +trail(0, X, Z); +trailLast(0, X, Z); !trailClock.
@trailPoint
+!trailClock : trailStep(S) & trailLast(N, Lx, Lz) & location(X, _, Z)
    <- if ((X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz) > S * S) { +trail(N + 1, X, Z); -+trailLast(N + 1, X, Z); if (followingWall(_, _, _)) { +trailAlong(N + 1, X, Z) } };
       .wait(500); !trailClock.
@trailWait +!trailClock <- .wait(500); !trailClock.

// P more than B past the wall met on the way from (X, Z) to (Tx, Tz), along the axis nearest that way
pastBy(X, Z, Tx, Tz, Px, _, B) :- math.abs(Tx - X) >= math.abs(Tz - Z) & (Px - X) * (Tx - X) / math.abs(Tx - X) > B.
pastBy(X, Z, Tx, Tz, _, Pz, B) :- math.abs(Tx - X) < math.abs(Tz - Z) & (Pz - Z) * (Tz - Z) / math.abs(Tz - Z) > B.
beyondWall(X, Z, Tx, Tz, Px, Pz) :- trailPast(B) & pastBy(X, Z, Tx, Tz, Px, Pz, B).
// a point past the wall: any trail point past it by trailPast, or one laid along a wall by trailPastAlong
pastWall(X, Z, Tx, Tz, N, Px, Pz) :- trail(N, Px, Pz) & beyondWall(X, Z, Tx, Tz, Px, Pz).
pastWall(X, Z, Tx, Tz, N, Px, Pz) :- trailAlong(N, Px, Pz) & not beyondWall(X, Z, Tx, Tz, Px, Pz) & trailPastAlong(B) & pastBy(X, Z, Tx, Tz, Px, Pz, B).
// how far P lies along the wall to the robot's left as it faces the target (heading D: the left is D - 90)
leftOfWay(X, Z, Tx, Tz, D, Px, Pz, Lw) :- math.abs(Tx - X) >= math.abs(Tz - Z) & Lw = (Pz - Z) * math.sin((D - 90) * math.pi / 180).
leftOfWay(X, Z, Tx, Tz, D, Px, Pz, Lw) :- math.abs(Tx - X) < math.abs(Tz - Z) & Lw = (Px - X) * math.cos((D - 90) * math.pi / 180).

// the way the robot came: to its left means the wall on the right
@chooseSideByTrail
+!chooseSide(S) : trailStep(_) & location(X, _, Z) & goingTo(Tx, Tz) & pastWall(X, Z, Tx, Tz, _, _, _)
    <- .findall(t(N, Px, Pz), pastWall(X, Z, Tx, Tz, N, Px, Pz), Ps); .max(Ps, t(_, Bx, Bz));
       computeAngle(X, Z, Tx, Tz, D); ?leftOfWay(X, Z, Tx, Tz, D, Bx, Bz, Lw);
       if (Lw > 0) { S0 = right } else { S0 = left };
       if (gaveUpSide(S0) & not (gaveUpSide(right) & gaveUpSide(left))) { !otherSide(S0, S) } else { S = S0 }.
