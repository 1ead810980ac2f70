// Skill: one robot at a time at the storage point (thesis Chapter 6, multi-robot coordination; not
// in the thesis). Every delivery ends at the one storage point, where a robot puts its cylinder
// down without looking (delivery: no distance sensing inside the area), so two robots there
// touched each other. A robot bringing a cylinder asks the task board for its turn when it comes
// within storageQueueRadius of the storage point; if another robot has it, it stops where it is
// (out of the area: the area's access radius is 0.15 m) and waits, then goes on. It gives the
// turn up once storageLeaveClearance out of the area after it left it (-insideArea), so that the
// next robot does not drive in while it still turns and leaves (handing it over at the area's
// edge made them touch), or when the delivery ends or pauses before it got in.
// Parameters:
storageQueueRadius(0.35).   // m from the storage point where a robot with a cylinder asks its turn
storageTurnLimit(60000).    // ms a turn may last (a robot stuck inside must not keep the others out)
storageLeaveClearance(0.3). // m out of the area (storageClearance, delivery's) where a robot gives its turn up
storageLeaveTimeout(15000). // ms it may take to get that far (boxed in, it gives the turn up then)
// Beliefs: waitingStorage, storageTurnMine, storageTurnSince(T), storageLeaving(T). Rules it extends: halted, waitingTurn.
// Reads: delivering, insideArea, picking, onErrand (delivery, recharge), storagePoint(X, Z) (the world),
// location; the middleware's stuck.
// Needs: team-way (!standStill), delivery (computeGap, balance, desired), the board focused (team-claims). Include it first (its
// +location plan applies now and then, team-places' almost always), before
// delivery, heading and avoidance: its plans for obstacles while waiting come first.

halted :- waitingStorage.
waitingTurn :- waitingStorage.
awayFromStorage(X, Z) :- storagePoint(Sx, Sz) & storageClearance(C) & storageLeaveClearance(L)
    & (X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz) >= (C + L) * (C + L).

@askStorageTurn[atomic]
+location(X, _, Z) : delivering & not onErrand & not insideArea & not storageTurnMine & not waitingStorage
                    & storagePoint(Sx, Sz) & storageQueueRadius(R) & (X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz) < R * R
    <- +waitingStorage; !!storageTurn.

// out of the area after a delivery, the turn is given up once far enough (driven by the GPS
// percept: no dropped desire, a fallen cylinder's, can keep the turn for good)
@storageTurnAway[atomic]
+location(X, _, Z) : storageLeaving(T0) & (awayFromStorage(X, Z) | .system_time(T) & storageLeaveTimeout(L) & T - T0 > L)
    <- -storageLeaving(_); if (storageTurnMine) { !giveStorageTurn }.

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
// the delivery ended or paused before the area was reached (a fall, a low battery)
@storageNotReached -delivering : storageTurnMine & not insideArea <- !giveStorageTurn.
@storageChargingFirst +charging : storageTurnMine & not insideArea <- !giveStorageTurn.
@storageWaitCharging +charging : waitingStorage <- storageDone; -waitingStorage.

// while waiting for its turn the robot stands still: obstacles (a robot leaving the area) and the
// missing progress are no reason to move
@obstacleWhileWaitingStorage +obstacle(true) : waitingStorage.
@lateralWhileWaitingStorage +lateralObstacle(_) : waitingStorage.
@stuckWhileWaitingStorage +stuck : waitingStorage.
