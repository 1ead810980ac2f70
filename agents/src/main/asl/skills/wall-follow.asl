// Skill: following a wall once new floor stops coming (not in the thesis), on only in an agent that
// believes followWalls (measured, not kept: docs/comparison-obstacle-avoidance.md, "a wall
// following to the doorway"). In a users' arena of rooms the random walk covers the robot's own room
// and then goes over it again, while the room behind a doorway or corridor stays unvisited: the
// doorway is on the room's wall, and the random walk seldom meets it square. So, in an arena of
// looseArea m2 or more (coverage.asl), once fewer than followBelow cells were new in the last
// followWindow ms while the crossed floor spans under followSpan of the arena's diagonal, the robot
// follows the wall on the side whose sensor reads more for followTime ms: that sensor's reading held
// in followBand by bearing away from the wall or going straight; where the wall ends (a doorway's
// jamb) it passes the end and turns a quarter turn round it. The avoidance of coverage.asl still
// turns it from the corners. A follow that turned followIsland degrees net towards its wall's side
// went round a box standing free, not the room's wall: it ends there; new floor again ends it too.
// A follow that ran its full time without new floor is the last of the run: the doorway is out of
// reach of the follow (too narrow, or none), and the random walk had crossed some the follow missed.
// Parameters (timings in ms):
followWindow(30000).
followBelow(10).
// the crossed floor (dead reckoning) spans under followSpan of the arena's diagonal: the robot has
// stayed in a part of the arena (a room); in a hall whose floor comes slowly a follow only took
// time from the random walk
followSpan(0.85).
followLookEvery(5000).   // while new floor still comes, the next count
followTime(90000).
// a side sensor (20° off the axis, ±15°) reads about 25 with a wall alongside 11 cm from the
// robot's centre and 90 at 7.5 cm (MyBot's table); well under the left-right difference that
// signals an obstacle
followBand(25, 90).
followBear(0.5).         // the inner wheel's share of cruiseSpeed when bearing
followStep(120).         // ms between two steering decisions
// where the wall ends, straight on for followPass ms first: the sensor loses it when its end is
// some 15 cm ahead of the robot's centre, and bearing at once swept the blind flank into the jamb
followPass(1700).
// then a quarter turn round its end on a tight arc, whatever the sensor reads during it (the inner
// wheel at followRound of cruiseSpeed: 8 cm radius, the body clear of the end and within 15 cm of
// it): into a doorway or corridor of 15 cm or more; the far jamb coming into sight while bearing
// turned the robot back along the wall before
followRound(0.3).
followRoundTurn(90).     // degrees
// new floor again (followFound cells in the last followFoundWindow ms): out of the used-up room,
// the follow ends and coverage takes over there (followed on, the wall led round the new room and
// back through the doorway)
followFound(8).
followFoundWindow(10000).
followIsland(450).
followOn :- followWalls & arena(W, D) & looseArea(A) & W * D >= A.
followLookDue(T) :- .system_time(T) & followWindow(W) & T > W & not (nextFollowLook(L) & T < L).
// the last time the wall (or an obstacle) was in sight
wallLastSeen(S) :- wallSeen(S) & not (obstacleTimes([O | _]) & O > S).
wallLastSeen(O) :- obstacleTimes([O | _]).
// the wall followed is on the side whose sensor reads more when the follow begins (right on a tie)
wallSide(left) :- leftSensor(L) & rightSensor(R) & L > R.
wallSide(right).
sideReading(left, X) :- leftSensor(X).
sideReading(right, X) :- rightSensor(X).
sideSign(left, -1).
sideSign(right, 1).
// wheel speeds (left, right) to bear away from or towards the wall's side, the inner wheel at share B
steer(right, away, V, B, L, R) :- L = V * B & R = V.
steer(right, toward, V, B, L, R) :- L = V & R = V * B.
steer(left, away, V, B, L, R) :- L = V & R = V * B.
steer(left, toward, V, B, L, R) :- L = V * B & R = V.
// Reads: arena(W, D) (the world); looseArea, cruiseSpeed, obstacleTimes and the rule pausedUntil
// (coverage.asl); leftSensor, rightSensor and obstacle (the middleware); followWalls (the
// agent's). Include it before coverage.asl: its move plans come first while a follow runs.

@followLook
+!move(N) : followOn & not followGaveUp & not following(_, _, _) & not pausedUntil(_) & followLookDue(T) & followWindow(W) & followBelow(K)
    <- freshCells(W, C); visitedSpan(Span); ?arena(AW, AD); ?followSpan(FS);
       if (C < K & Span < FS * math.sqrt(AW * AW + AD * AD)) {
           ?followTime(D); headingTurned(H); ?wallSide(Side); +following(T + D, H, Side); -+wallSeen(T); -+nextFollowLook(T + D + W);
           println("No new floor: following the wall")
       } else { ?followLookEvery(E); -+nextFollowLook(T + E) };
       !move(N).
@followEnd +!move(N) : following(U, H, Side) & .system_time(T) & T >= U <- -following(U, H, Side); +followGaveUp; !move(N).
@followFound
+!move(N) : following(U, H, Side) & followFoundWindow(FW) & followTime(D) & .system_time(T) & T > U - D + FW
          & not checkedFound(T)
    <- freshCells(FW, C); ?followFound(K);
       if (C >= K) { -following(U, H, Side); ?followWindow(W); -+nextFollowLook(T + W); println("New floor: the wall following ends") } else { -+checkedFound(T) };
       !move(N).
// one steering decision; an obstacle ends it (coverage's @coverObstacle), the avoidance runs, then
// the next decision finds the wall again
@followStep
+!move(_) : following(U, H0, Side) & not pausedUntil(_) & obstacle(false) & sideReading(Side, R) & followBand(Lo, Hi)
          & cruiseSpeed(V) & followBear(B) & followStep(S) & .system_time(T)
    <- headingTurned(H); ?followIsland(I); ?sideSign(Side, Sg);
       if ((H0 - H) * Sg > I) {
           -following(U, H0, Side); ?followLookEvery(E); -+nextFollowLook(T + E); println("Round a box: the wall following ends")
       } else {
           if (R > Hi) { ?steer(Side, away, V, B, L, Rw); setSpeeds(L, Rw); -+wallSeen(T) }
           else {
               if (R >= Lo) { setSpeeds(V, V); -+wallSeen(T) }
               else {
                   ?wallLastSeen(Seen); ?followPass(P);
                   if (T - Seen >= P & not rounded(Seen)) { -+rounded(Seen); !roundEnd(V, Side) } else { setSpeeds(V, V) }
               }
           };
           .wait(S)
       }.

// the quarter turn round a wall's end: an obstacle ends it (coverage's @coverObstacle ends the move)
@followRoundEnd
+!roundEnd(V, Side) : followRound(RB) & followRoundTurn(Deg) & wheelGeometry(U, A) & steer(Side, toward, V, RB, L, R)
    <- setSpeeds(L, R); .wait(Deg / 180 * 3.14159 * A / (V * U * (1 - RB)) * 1000).
