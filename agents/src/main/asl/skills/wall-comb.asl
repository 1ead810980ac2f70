// Skill: the wall comb, not in the thesis. Once the robot's room gives no new floor (fewer than
// combBelow cells new in the last combWindow ms, the middleware's freshCells) while the floor crossed
// (visitedArea, dead reckoning) is under combShare of the arena, the rest of the arena lies behind a
// wall whose passage the random walk seldom meets square. For combTime ms the robot then combs a
// wall: it drives to the wall ahead, stops where a front sensor reads combNear (about 16 cm off,
// under every level that signals an obstacle), squares up (turns towards the sensor that reads more
// until the two differ by combTolerance or less), steps combStep m sideways (a quarter turn, the
// step, a quarter turn back) and drives to the wall again. Where the wall is not met again within
// combReach m the robot stands in a gap (a passage's mouth, or past the wall's end): the comb ends
// and the leg goes on straight through it.
// Reads: arena(W, D); leftSensor, rightSensor, obstacle (the middleware's); turnSpeed, cruiseSpeed,
// wheelGeometry, flankTime, obstacleTimes (coverage.asl); its own combing(Until, Side) and combedAt(T).
// Include it before coverage.asl (its move plans come first) and after nothing that moves.
// Parameters:
combWindow(30000).
combBelow(3).
combShare(0.6).
combTime(90000).
combNear(100).        // the front reading (about 16 cm from the rim) the robot stops at
combCap(140).         // nearer (a reading over it) the robot backs off before the step
combStep(0.04).       // the sideways step, m
combReach(0.04).      // the wall not met within this many m after a step (where it stood before): a gap
combFirst(3).         // how far, m, the first drive to a wall may go
combWalls(4).         // the walls combed in a run at most

@moveCombEnd +!move(N) : combing(U, _, _, _) & .system_time(T) & T >= U <- -combing(U, _, _, _); +combedAt(T); !move(N).
// a side step cut short by an obstacle: the wall ends there; the other way along it, then the next wall
@moveCombCut
+!move(N) : combing(U, Side, H, Cuts) & combStepping
    <- -combStepping; -combing(U, Side, H, Cuts);
       if (Cuts == 0) { if (Side == "left") { S2 = "right" } else { S2 = "left" }; +combing(U, S2, H, 1) }
       else { !combNextWall(H2); +combing(U, Side, H2, 0) };
       !move(N).
@moveComb
+!move(_) : combing(_, _, H, _) & not obstacle(true) & not avoiding & not veering & flankTime(FT) & .system_time(T)
          & not (obstacleTimes([L | _]) & T - L < FT) & combFirst(F) & turnSpeed(S)
    <- headingTurn(H, S, Side, Ms);
       if (Side == "left") { setSpeeds(-S, S) } else { setSpeeds(S, -S) }; .wait(Ms);
       !combDrive(F).
@moveCombStart
+!move(N) : N > 0.3 & not combing(_, _, _, _) & combEpisodes(E) & combWalls(MaxW) & E < MaxW & combWindow(W) & .system_time(T) & T > W & not (combedAt(F) & T - F < W)
    <- freshCells(W, C); visitedArea(Crossed); ?arena(AW, AD); ?combShare(Share); ?combBelow(K);
       if (C < K & Crossed < Share * AW * AD) {
           ?combTime(D); .random(R); if (R < 0.5) { Side = "left" } else { Side = "right" };
           !combNextWall(H); -combedAt(_); +combing(T + D, Side, H, 0); println("Room covered: combing a wall")
       } else { -+combedAt(T) };
       !move(N).

// the next wall of the room to comb, from the robot's map (the middleware's combHeading)
@combNextWall +!combNextWall(H) : arena(AW, AD) & combEpisodes(K) <- combHeading(AW, AD, K, H); -+combEpisodes(K + 1).
combEpisodes(0).

// to the wall ahead, at most Reach m; none met: a gap, the comb ends and the leg goes on
@combDrive +!combDrive(Reach) : cruiseSpeed(V) & wheelGeometry(U, _) <- setSpeeds(V, V); !combAhead(Reach / (V * U) * 1000).
@combAtWall
+!combAhead(_) : leftSensor(L) & rightSensor(R) & combNear(K) & (L >= K | R >= K)
    <- stop; !combBack(25); !combSideStep.
@combGap
+!combAhead(Ms) : Ms <= 0 & combing(U, S, H, C) & .system_time(T)
    <- -combing(U, S, H, C); +combedAt(T); println("Combing: a gap"); !straightLeg.
@combAheadOn +!combAhead(Ms) : combing(_, _, _, _) <- .wait(40); !combAhead(Ms - 40).
@combAheadEnd +!combAhead(_).

// too near to turn a quarter without the avoidance's difference: back off, 40 ms at a time
@combBackOff
+!combBack(K) : K > 0 & leftSensor(L) & rightSensor(R) & combCap(C) & math.max(L, R) > C & cruiseSpeed(V)
    <- setSpeeds(-V, -V); .wait(40); !combBack(K - 1).
@combBackDone +!combBack(_) <- stop.

// a quarter turn to the comb's side, the step, a quarter turn back, and to the wall again
@combSideStep
+!combSideStep : combing(_, Side, H, _) & turnSpeed(S) & cruiseSpeed(V) & wheelGeometry(U, A) & combStep(D) & combReach(Reach)
    <- Q = 1000 * (3.14159265 / 2) / (2 * S * U / A); +combStepping;
       if (Side == "left") { setSpeeds(-S, S) } else { setSpeeds(S, -S) }; .wait(Q);
       setSpeeds(V, V); .wait(D / (V * U) * 1000);
       headingTurn(H, S, Back, Ms); if (Back == "left") { setSpeeds(-S, S) } else { setSpeeds(S, -S) }; .wait(Ms);
       -combStepping; !combDrive(Reach).
@combSideStepEnd +!combSideStep.
