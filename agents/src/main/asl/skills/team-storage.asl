// Skill: one robot at a time at the storage point (thesis Chapter 6, multi-robot coordination; not
// in the thesis). Every delivery ends at the one storage point, where a robot puts its cylinder
// down without looking (delivery: no distance sensing inside the area), so two robots there
// touched each other. A robot bringing a cylinder asks the task board for its turn when it comes
// within storageQueueRadius of the storage point; if another robot has it, it stops where it is
// (out of the area: the area's access radius is 0.15 m) and waits, then goes on. It gives the
// turn up once storageLeaveClearance out of the area after it left it (-insideArea), so that the
// next robot does not drive in while it still turns and leaves (handing it over at the area's
// edge made them touch), or when the delivery ends or pauses before it got in.
// Not in the thesis either: while a teammate waits for the turn, the holder clears out. Its half turn
// after the put-down is quick (heading's quickTurn: the listing's slow turn took 12 s), and out of
// the area it drives straight off, away from the storage point and from the teammate waiting, until
// it gives the turn up; the sweep's look around (a full turn on the spot at the area's edge, 7 s, the
// first thing a robot did out of the area) comes after. The turn was held until storageLeaveTimeout
// in five turns of six (team tuning worlds 1-6, two robots), the holder turning on the spot or
// creeping along the corner's wall meanwhile. The turn is still given up only at the clearance (an
// earlier hand-over made robots touch). The way off keeps off the arena's walls (clearOutMargin): a
// way off into the wall beside the storage area was turned away by avoidance and back by the next
// step, 0.14 m in 16 s (team world 4). If storageLeaveTimeout comes first and a look around is due,
// the holder makes it while it still holds the turn (a look made after it, near the area, was
// driven onto by the next robot).
// Not in the thesis either: the turn is handed over as soon as the holder, out of the area, is on
// the far side of the storage point from the teammate waiting and handOverGap from it (that one
// drives in away from it); the holder still clears out until it is away (or storageLeaveTimeout).
// The turn was given up by storageLeaveTimeout in 44 of 55 turns (team tuning worlds 1-8, two
// robots), the teammate standing meanwhile.
// Parameters:
storageQueueRadius(0.35).   // m from the storage point where a robot with a cylinder asks its turn
storageTurnLimit(60000).    // ms a turn may last (a robot stuck inside must not keep the others out)
storageLeaveClearance(0.3). // m out of the area (storageClearance, delivery's) where a robot gives its turn up
storageLeaveTimeout(15000). // ms it may take to get that far (boxed in, it gives the turn up then)
clearOutStep(1000).         // ms of one step straight off while clearing out (then the heading again)
clearOutMargin(0.2).        // m from the arena's wall within which the way off does not lead towards it
lookInTurnLimit(9000).      // ms after storageLeaveTimeout the turn is kept for a look around (it lasts 7 s)
handOverGap(0.3).           // m between the holder and the teammate waiting for an early hand-over
// Beliefs: waitingStorage, storageTurnMine, storageTurnSince(T), storageLeaving(T), lookInTurn(T), handedOverTo(A). Rules it extends: halted, waitingTurn,
// quickTurn(V, A) (heading's).
// Reads: storageQueue(L), robotAt(A, X, Z) (the board), arena(W, D), searching, lastLook(T), lookEvery(L) (sweep), quickTurnAt(V, A) (heading), travelSpeed(V) (far-sight), justAvoided(T) (sweep), delivering, insideArea, picking, onErrand (delivery, recharge), storagePoint(X, Z) (the world),
// location; the middleware's stuck.
// Needs: team-way (!standStill), delivery (computeGap, balance, desired), the board focused (team-claims). Include it first (its
// +location plan applies now and then, team-places' almost always), before
// delivery, heading and avoidance: its plans for obstacles while waiting come first.

halted :- waitingStorage.
waitingTurn :- waitingStorage.
awayFromStorage(X, Z) :- storagePoint(Sx, Sz) & storageClearance(C) & storageLeaveClearance(L)
    & (X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz) >= (C + L) * (C + L).
// a teammate waits for this robot's turn
turnWaitedFor(W) :- .my_name(Me) & storageQueue([Me, W | _]).
quickTurn(V, A) :- storageTurnMine & turnWaitedFor(_) & quickTurnAt(V, A).
// the teammate this robot clears out from: the one waiting for its turn, or the one it handed the turn to
clearingFrom(W) :- storageTurnMine & turnWaitedFor(W).
clearingFrom(W) :- handedOverTo(W).
// out of the area on the far side of the storage point from the teammate waiting, and apart from it
handOverBehind(X, Z) :- turnWaitedFor(W) & robotAt(W, Wx, Wz) & storagePoint(Sx, Sz) & handOverGap(G)
    & (X - Sx) * (Wx - Sx) + (Z - Sz) * (Wz - Sz) < 0 & (X - Wx) * (X - Wx) + (Z - Wz) * (Z - Wz) >= G * G.
// the way off: away from the storage point and from the teammate waiting (the sum of the two unit
// vectors); with that teammate straight ahead on the way out, square to it, on the arena centre's side
clearOutTo(Tx, Tz) :- location(X, _, Z) & storagePoint(Sx, Sz) & clearingFrom(W) & robotAt(W, Wx, Wz)
    & Ds = math.sqrt((X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz)) & Dw = math.sqrt((X - Wx) * (X - Wx) + (Z - Wz) * (Z - Wz))
    & Ds > 0 & Dw > 0 & Ux = (X - Sx) / Ds & Uz = (Z - Sz) / Ds
    & Vx = Ux + (X - Wx) / Dw & Vz = Uz + (Z - Wz) / Dw & clearOutWay(X, Z, Ux, Uz, Vx, Vz, Ax, Az)
    & clearOutFree(X, Z, Ax - X, Az - Z, Ux, Uz, Tx, Tz).
clearOutWay(X, Z, _, _, Vx, Vz, Tx, Tz) :- Vx * Vx + Vz * Vz >= 0.25 & Tx = X + Vx & Tz = Z + Vz.
clearOutWay(X, Z, Ux, Uz, Vx, Vz, Tx, Tz) :- Vx * Vx + Vz * Vz < 0.25 & Uz * X - Ux * Z < 0 & Tx = X + Uz & Tz = Z - Ux.
clearOutWay(X, Z, Ux, Uz, Vx, Vz, Tx, Tz) :- Vx * Vx + Vz * Vz < 0.25 & Uz * X - Ux * Z >= 0 & Tx = X - Uz & Tz = Z + Ux.
// off the walls: near a wall, the part of the way towards it is dropped; the way kept if most of it
// is left and it does not lead back towards the storage point, else the way straight away from the
// point (kept off the walls the same way), else the arena's centre
clearOutFree(X, Z, Vx, Vz, Ux, Uz, Tx, Tz) :- offWalls(X, Z, Vx, Vz, Fx, Fz) & Fx * Fx + Fz * Fz >= 0.25 * (Vx * Vx + Vz * Vz)
    & Fx * Ux + Fz * Uz >= 0 & Tx = X + Fx & Tz = Z + Fz.
clearOutFree(X, Z, _, _, Ux, Uz, Tx, Tz) :- offWalls(X, Z, Ux, Uz, Fx, Fz) & Fx * Fx + Fz * Fz >= 0.25 & Tx = X + Fx & Tz = Z + Fz.
clearOutFree(_, _, _, _, _, _, 0, 0).
offWalls(X, Z, Vx, Vz, Fx, Fz) :- arena(W, D) & clearOutMargin(M) & Hx = W / 2 - M & Hz = D / 2 - M
    & offWall(X, Vx, Hx, Fx) & offWall(Z, Vz, Hz, Fz).
offWall(X, V, H, V) :- V >= 0 & X <= H.
offWall(X, V, H, V) :- V <= 0 & X >= -H.
offWall(X, V, H, 0) :- V > 0 & X > H.
offWall(X, V, H, 0) :- V < 0 & X < -H.

@askStorageTurn[atomic]
+location(X, _, Z) : delivering & not onErrand & not insideArea & not storageTurnMine & not waitingStorage
                    & storagePoint(Sx, Sz) & storageQueueRadius(R) & (X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz) < R * R
    <- +waitingStorage; !!storageTurn.

// out of the area after a delivery, the turn is given up once far enough (driven by the GPS
// percept: no dropped desire, a fallen cylinder's, can keep the turn for good)
@storageTurnAway[atomic]
+location(X, _, Z) : storageLeaving(T0) & (awayFromStorage(X, Z) | .system_time(T) & storageLeaveTimeout(L) & T - T0 > L)
    <- -storageLeaving(_); -handedOverTo(_); .system_time(Now);
       if (storageTurnMine & not awayFromStorage(X, Z) & turnWaitedFor(_) & searching & lookEvery(E) & lastLook(Lk)
           & Now - Lk > E) { +lookInTurn(Now) }
       elif (storageTurnMine) { !giveStorageTurn }.
// the early hand-over: the turn given up, the clearing out goes on (storageLeaving kept)
@storageHandOver[atomic]
+location(X, _, Z) : storageLeaving(_) & storageTurnMine & handOverBehind(X, Z) & turnWaitedFor(W)
    <- +handedOverTo(W); !giveStorageTurn.
// the look around made inside the turn (@lookInTurn): the turn given up lookInTurnLimit after the
// timeout if the look did not end (a sighting cut it short, or the robot stopped searching)
@lookInTurnOver[atomic]
+location(_, _, _) : lookInTurn(T0) & .system_time(T) & lookInTurnLimit(M) & T - T0 > M
    <- -lookInTurn(_); if (storageTurnMine) { !giveStorageTurn }.

// out of the area with a teammate waiting for the turn: a step straight off instead of the sweep's
// step (its look around and its waypoint come once the turn is given up); sweep's !sweepStep. Just
// after an avoidance it drives on first, as the sweep does (a box on the way off turned it back and forth)
@clearOutStep
+!sweepStep : storageLeaving(_) & clearOutTo(Tx, Tz) & location(X, _, Z)
              & travelSpeed(V) & clearOutStep(T)
    <- .system_time(Now); if (justAvoided(Now)) { forward; .wait(T) };
       ?location(X2, _, Z2); computeAngle(X2, Z2, Tx, Tz, A); -+desired(A); !balance; setSpeeds(V, V); .wait(T).
// the storage turn's timeout came first: sweep's look around, then the turn given up
@lookInTurn
+!sweepStep : lookInTurn(T0) & lastLook(L) & L < T0
    <- !lookAround; -lookInTurn(_); if (storageTurnMine) { !giveStorageTurn }.

@storageTurnFree +!storageTurn : storageQueue([]) <- awaitStorageTurn; !storageTurnTaken.
@storageTurnBusy
+!storageTurn <- !standStill; .print("Waiting for the storage area"); awaitStorageTurn; !storageTurnTaken; !computeGap; !balance.
@storageTurnLost -!storageTurn <- -waitingStorage.
@storageTurnTaken
+!storageTurnTaken : .system_time(T) <- +storageTurnMine; -+storageTurnSince(T); -waitingStorage; !!storageTurnWatch(T).

// the watch ends only the turn it was started for (an earlier turn's watch cut a later turn short,
// and the next robot drove in on a robot still in the area)
@storageTurnWatch +!storageTurnWatch(T0) : storageTurnLimit(T) <- .wait(T); !storageTurnOver(T0).
@storageTurnOverdue
+!storageTurnOver(T0) : storageTurnMine & storageTurnSince(T0) <- .print("Storage turn over: next robot"); !giveStorageTurn.
@storageTurnOverAlready +!storageTurnOver(_).

@giveStorageTurn +!giveStorageTurn <- -storageTurnMine; storageDone.

// out of the area after a delivery, or a fallen cylinder (delivery forgets insideArea): the turn
// is kept until the robot is away (storageTurnAway)
@storageLeft -insideArea : storageTurnMine & .system_time(T) <- -+storageLeaving(T).
// back in the area with another cylinder (one picked beside it while the turn was still held): the
// leaving is over, so its storageLeaveTimeout does not give the turn up while this cylinder is put
// down (it did, and the robot waiting drove in onto it: team world 25, four robots, 8.7 s); the next
// -insideArea starts the leaving again
@storageBackIn +insideArea : storageLeaving(_) & storageTurnMine <- -storageLeaving(_); -handedOverTo(_).
// the delivery ended or paused before the area was reached (a fall, a low battery)
@storageNotReached -delivering : storageTurnMine & not insideArea <- !giveStorageTurn.
@storageChargingFirst +charging : storageTurnMine & not insideArea <- !giveStorageTurn.
@storageWaitCharging +charging : waitingStorage <- storageDone; -waitingStorage.

// while waiting for its turn the robot stands still: obstacles (a robot leaving the area) and the
// missing progress are no reason to move
@obstacleWhileWaitingStorage +obstacle(true) : waitingStorage.
@lateralWhileWaitingStorage +lateralObstacle(_) : waitingStorage.
@stuckWhileWaitingStorage +stuck : waitingStorage.
