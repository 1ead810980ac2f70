// Tidy-up (not in the thesis): every cylinder to the storage area, recharging when needed, then park on the charger; skills and its own plans for when
// the task is done and when to search (no way round). Told: cylinders(N), storagePoint(X, Z), storageRadius(R), charger(X, Z), arena(W, D); taskEnd(Ms).
middlewareClass("jacabot.experiments.SuspendResumeMiddleware").
// a search goes on from anywhere (no way back after a recharge), a look around first, the sweep after 5 s; a delivery under way ends first while the battery
// less 150 J covers the way on to the charger, and goes on while less 50 J (a drain came); a homing still nearing goes on past far sight's limit (a nearer
// sighting in the last 15 s); every red run seen; turns at half speed but for the last 15 degrees; no trip while the battery covers the time left, a charge
// ends once it covers it and 100 J (2 W); near approach at 85; a waypoint given up at the storage area's edge only when it lies past the storage point;
// parked, whatever is counted, once the time left is under 32 s a metre to the charger and 15 s and the sweep has taken all its lanes' waypoints
resumeAtCharger. lookFirst. searchDelay(5000). deliverFirst(150). deliverOn(50). homingProgress(15000). everyRedRun. quickTurns. chargeUntilLasts(100). meanPower(2). quickApproach(85). waypointPastStorage. parkInTime(32, 15).
!start.
// trips and waypoints through the robot's own map (route), a way out of the storage corner; near the storage point
// re-aligned when 3 degrees off, not 10 (else it passed it 4 cm aside); a knocked cylinder no obstacle (knocked-aside)
offBy(3) :- delivering & targetPoint(Tx, Tz) & nearTarget(Tx, Tz).
{ include("skills/initial-phase.asl") }
{ include("skills/route.asl") }
{ include("skills/storage-exit.asl") }
{ include("skills/recharge.asl") }
{ include("skills/delivery.asl") }
{ include("skills/knocked-aside.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
{ include("skills/search-memory.asl") }
{ include("skills/recovery.asl") }
{ include("skills/progress-watch.asl") }
{ include("skills/sweep.asl") }
{ include("skills/random-walk.asl") }

// after each delivery and each recharge: is every cylinder stored? If not, a look around first
@doneDelivering -~delivered <- +lookFirst; !parkIfDone.
@doneRecharging -charging <- +lookFirst; !parkIfDone.
// parking is a trip to the charger that keeps "charging" (the task stays suspended, for good)
@park
+!parkIfDone : stored(N) & cylinders(N) & not charging
    <- .print("All ", N, " cylinders stored: parking on the charger"); +charging; !goToCharger;
       stopAcquireDistance; .print("Parked on the charger").
// not done: look for the rest, where a cylinder was seen first (search-memory)
@searchOn +!parkIfDone : not delivering & not picked(true) <- !searchFromMemory.
@notDone +!parkIfDone.
