// Skill: a drive to the nearest uncrossed region (not in the thesis; a frontier in the sense of ROS'
// explore_lite), for the two-sensor MyBot with coverage.asl's map, on only in an agent that
// believes floorDrive(Window, Below, Bound): once fewer than Below cells were new in the last Window
// ms, legs to the nearest region of floor neither crossed nor marked (the middleware's regionTurn,
// regionShape's Radius and Cells) along floor crossed, a waypoint at a time, until new floor comes
// (newFloor) or Bound ms have gone; then Window ms of random motion before the next look.
// Avoidance stays in charge: an obstacle ends a leg (coverage.asl's @coverObstacle), and within
// flankTime of one coverage.asl's straight leg leaves it. Include it before coverage.asl.
regionShape(3, 30).
newFloor(2000, 2).            // the drive has arrived: this many cells new within that many ms
driveLookEvery(5000).         // while new floor still comes, the next look at its rate
// the walls and boxes read at this level or more (about 12 cm from the sensor) end a region and the
// way to it, in every arena (coverage.asl's wallMarks only from looseArea): unmarked, the floor
// beyond a small arena's wall counted as an uncrossed region, and the drive went into the wall
regionWallLevel(200).
setUpGoal(setUpFloorDrive).
// Reads: floorDrive(W, K, B) (the agent's); flankTime, turnSpeed, cruiseSpeed, wheelGeometry,
// obstacleTimes, pausedUntil (coverage.asl's); its own driving(Until) and droveAt(T).

@setUpFloorDrive +!setUpFloorDrive : floorDrive(_, _, _) & regionWallLevel(L)
    <- regionWalls(L); if (doorOpen) { forgetCrossedMarks }; if (doorOpenTurns) { forgetCrossedTurns }; if (regionFar(F)) { regionFar(F) }; if (doorSeen(A, B, R, S)) { openSeenFloor(A, B, R, S) }.
@setUpNoFloorDrive +!setUpFloorDrive.

@driveLeg
+!move(N) : driving(U) & .system_time(T) & T < U & not pausedUntil(_) & not obstacle(true) & flankTime(FT)
          & not (obstacleTimes([L | _]) & T - L < FT) & turnSpeed(S) & cruiseSpeed(V) & wheelGeometry(Unit, _)
          & regionShape(R, C) & newFloor(NW, NK)
    <- freshCells(NW, New);
       if (New >= NK) { -driving(U); -+droveAt(T); println("New floor reached: random motion again"); !move(N) }
       else {
           regionTurn(S, R, C, Side, Ms, D);
           if (Side == "none") { -driving(U); -+droveAt(T); println("No uncrossed region left: random motion again"); !move(N) }
           else {
               if (Side == "left") { setSpeeds(-S, S) } else { setSpeeds(S, -S) }; .wait(Ms);
               setSpeeds(V, V); .wait(D / (V * Unit) * 1000)
           }
       }.
@driveEnd +!move(N) : driving(U) & .system_time(T) & T >= U <- -driving(U); -+droveAt(T); if (doorSeen(_, _, _, _) & seenForget) { forgetSeenFloor }; !move(N).
@driveStart
+!move(N) : floorDrive(W, K, B) & not driving(_) & not pausedUntil(_) & .system_time(T) & T > W & not (droveAt(F) & T - F < W)
    <- freshCells(W, C);
       if (C < K) { +driving(T + B); println("No new floor: driving to the nearest uncrossed region") }
       else { ?driveLookEvery(E); -+droveAt(T - W + E) };
       !move(N).
