// Skill: the trip to the charger and back (thesis Chapter 4 §4.1 and Appendix B). When the battery
// runs low (lowBattery) the task is suspended (!suspendTask, "charging" believed), the robot marks
// its orientation and the position where the battery went low (@lowBatteryFrom), goes to the
// charger, waits there for the charge, comes back to the marked point, and the task resumes
// (!resumeTask(Orientation)).
// Parameters:
lowBatteryLevel(480).   // J: the middleware signals lowBattery under it
chargedLevel(900).      // J: and charged over it
tripTimeout(150000).    // ms for the trip to the charger or back (recovery, not in the thesis)
wayEnergy(50).          // J a metre at full speed (the Khepera: 2.5 W at 5 cm/s): deliverFirst, team-charger
fullPower(2.5).         // W: both wheels at full speed (the Khepera): taskEnd
markedProgress(0.3).    // m nearer the marked point in one tripTimeout for the way back to go on
parkAfterPick(10000).   // ms: with parkInTime, no park as soon after a pick ended (a cylinder at hand)
// Reads: charger(X, Z), storagePoint(X, Z), cylinders(N) when known (the world file); ~delivered,
// stored(N) (delivery); lastFound(T), searching (sweep's, with deliverOn, parkInTime); picking, picked (picking's), homing (far
// sight's), sweep(L) (sweep's lanes, turned one waypoint on at each waypoint taken), with parkInTime.
// Beliefs: charging, atCharger, lowFrom(X, Y, Z) (where the low-battery episode began, until its trip begins), deliveringFirst(T) (the delivery of the cylinder picked at T went on first), markedFrom(D) (the way back's distance left when its try began);
// markedTryFrom(X, Z, Fx, Fz) (with markedByRoute: where the last try of the way back to the marked point (X, Z) began, when it was
// given another); resumeAtCharger (the agent's, optional: no way back to the marked point); markedByRoute (the agent's, optional: see
// @reachMarkedAlongRoute); deliverFirst(Reserve) (the agent's, optional: a delivery under way nearer the storage
// point than the charger, or the last, ends first while the battery less Reserve J covers the way
// via the storage point to the charger); taskEnd(T) (optional, the launcher tells tidy-up its run's end:
// the task's end, ms on the agent's clock: no trip while the battery covers the time left at full power);
// deliverOn(R) (the agent's, optional: see @deliveryKeptOn); chargeUntilLasts(R) (the agent's, optional, with taskEnd: a charge ends once the battery less R J
// covers the time left at full power, or at chargedLevel); meanPower(W) (the agent's, optional: the
// power those two sums assume instead of fullPower); parkInTime(S, M) (the agent's, optional, with taskEnd: see
// @parkAtTheEnd; pickEnded(T), lanesTaken(K) and sweptRound, its beliefs). Rules it extends:
// travelling, halted.
// Needs: heading (computeGap, balance, steer, the target point), recovery (!escape), with markedByRoute a
// middleware with routeLength (NavigationMiddleware's route map), and the two
// hooks: +!suspendTask and +!resumeTask(O): recharge.asl's when the task is this agent's own,
// energy-agent.asl's when it is another agent's.
// Deviations from the listing: the listing waits 3 s at the charger (".wait(3000)"); with the
// world's 20 W charger that is 60 J, and the battery was low again within a minute. The robot
// stops, ignores its distance sensors (a wall next to the charger must not make it leave) and
// waits for the middleware's "charged" signal, two minutes at most. Charger and marked point are
// reached with a 3 cm threshold (the charger's radius is 6 cm); the storage point's threshold (ray)
// is restored afterwards. "!restoreOrientation(0)" restores the orientation marked when the battery
// went low.

travelling :- charging.
halted :- atCharger.
// deliverFirst: the storage point nearer than the charger, or the last cylinder to store, and the
// battery less the reserve covers the straight way to the storage point and on to the charger
wayCovered(R) :- battery(B) & location(X, _, Z) & storagePoint(Sx, Sz) & charger(Cx, Cz) & wayEnergy(E)
    & B - R > E * (math.sqrt((X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz)) + math.sqrt((Sx - Cx) * (Sx - Cx) + (Sz - Cz) * (Sz - Cz))).
markedDistance(D) :- targetPoint(Tx, Tz) & distanceTo(Tx, Tz, D).
storageNearer :- location(X, _, Z) & storagePoint(Sx, Sz) & charger(Cx, Cz)
    & (X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz) < (X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz).
lastToStore :- cylinders(M) & stored(N) & N + 1 >= M.
// a delivery under way (or a knocked cylinder's fetch) goes on before a trip: the storage point nearer
// or the last cylinder to store, and the battery less R covers the way (deliverFirst's and deliverOn's)
deliveryGoesOn(R) :- (~delivered | fetchingKnocked) & not charging & (storageNearer | lastToStore) & wayCovered(R).
// taskEnd: the battery covers the task's time left, the wheels at full speed all along, or at the
// agent's own meanPower(W): tidy-up's wheels are at full speed part of the time only (1.7-1.8 W on
// the whole), and a second trip the full-speed sum forced late in the run (370-494 s, 15 of 80
// generated worlds) took the time left for the last cylinder
spendingPower(P) :- meanPower(P).
spendingPower(P) :- not meanPower(_) & fullPower(P).
batteryLasts(Now) :- taskEnd(End) & Now < End & battery(B) & spendingPower(P) & B > P * (End - Now) / 1000.
setUpGoal(setUpRecharge).
forgetOnFall(atCharger).

@setUpRecharge
+!setUpRecharge : lowBatteryLevel(L) & chargedLevel(C) <- batteryLevels(L, C).

// The point to come back to is where the low-battery episode began: the first battery reading
// under lowBatteryLevel (the middleware's lowBattery condition, on the same reading) since the last
// trip began, though a plan above @rechargeSuspend put the trip off (suspend/resume's
// @rechargeOutOfArea: a put-down; deliverFirst; a teammate on the charger). The success criterion
// judges the way back against that point (within 0.15 m): a trip begun out of the storage area
// 5 s after the episode marked its own start, 0.151 m off (held out, wide world 260, seed 2).
// The orientation restored is the trip's start's (the task's state when it was suspended).
@lowBatteryFrom[atomic]
+battery(B) : not charging & not lowFrom(_, _, _) & lowBatteryLevel(L) & B < L & B > 0 & location(X, Y, Z)
    <- +lowFrom(X, Y, Z).
episodeStart(X, Y, Z) :- lowFrom(X, Y, Z).
episodeStart(X, Y, Z) :- not lowFrom(_, _, _) & location(X, Y, Z).

// parkInTime(S, M): a task that ends parked on the charger (tidy-up) parks once the time left falls under
// S s a metre of the straight way to the charger and M s more, whatever it counts as done, while it
// searches (sweep's searching) with no cylinder caught, held or delivered (picking's picking, picked(true),
// delivery's ~delivered), not on a trip already. Its count of stored cylinders is its own deliveries, and
// a cylinder pushed into the storage area is not among them (no sensor sees the pile): the world counts
// it, the robot searched for it to the run's end, away from the charger (world 202 × 8). Not while a
// cylinder is at hand, nor while far sight homes on a sighting, nor parkAfterPick ms after a pick ended
// (pickEnded(T)): a park begun as a pick failed, the cylinder in front of the gripper, lost a run that
// caught it 1 s later, stored it and parked 0.5 s before the end (world 242 × 1)
parkDue(T) :- parkInTime(S, M) & taskEnd(End) & location(X, _, Z) & charger(Cx, Cz)
    & End - T < 1000 * (S * math.sqrt((X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz)) + M).
pickedLately(T) :- pickEnded(S) & parkAfterPick(W) & T - S < W.
@pickEndedNoted -picking : parkInTime(_, _) <- .system_time(T); -+pickEnded(T).
// Only on a sign that the count is wrong (sweptRound): since the search began or the last pick ended it,
// the sweep has taken as many waypoints as its lanes hold, so the round's last lane is under way
// (lanesTaken(K) counts the lists sweep believes while searching: one more at each waypoint taken).
// Without it a park left a search that still had time to end (32 s a metre is pessimistic): a run
// lost and a delivery less in five failed runs on generated worlds 1-50 × 1..3.
@lanesCounted[atomic] +sweep(L) : parkInTime(_, _) & searching
    <- if (lanesTaken(K)) { K1 = K + 1 } else { K1 = 1 }; -+lanesTaken(K1);
       if (K1 >= .length(L)) { +sweptRound }.
@lanesForgotten -searching : parkInTime(_, _) <- -lanesTaken(_); -sweptRound.
@parkAtTheEnd
+battery(_) : parkInTime(_, _) & searching & sweptRound & not charging & not picking & not ~delivered & not picked(true) & not homing(_)
    & .system_time(T) & not pickedLately(T) & parkDue(T)
    <- .print("Time is nearly up: parking on the charger"); +charging; !goToCharger; stopAcquireDistance;
       .print("Parked on the charger").
@stuckAtCharger +stuck : atCharger.
// on the charger nothing turns or cruises: the steering's re-alignment, begun in the control step
// the charger was reached, came after the trip's .drop_intention(balance) and drove the robot off
// the charger mid-charge (tidy-up, generated world 3)
@stayOnCharger +!balance : atCharger <- stop.

/* Low battery: suspend, recharge, come back, resume (Chapter 4 §4.1) */

// Recovery, not in the thesis: the waits for the charger, the charge and the marked point are
// bounded (!reachCharger, !waitCharged, !reachMarked); the robot steers on the way (!!steer).
// One trip per low battery: lowBattery comes every control step while the battery is low, and the
// signals queued meanwhile must find the robot charging already. The plan that believes "charging"
// is atomic, so no other lowBattery is considered before it (else each one started a trip).
// An agent whose task is a delivery that can wait no longer than the battery (tidy-up) finishes
// one under way first when the storage point is nearer than the charger: the way via the storage
// point to the charger is then the shorter, and a trip begun in the storage area left the robot
// halted there (insideArea) without steering, to run the battery empty against a wall. lowBattery
// comes again at the next control step, so the trip starts once the delivery is over.
// The last cylinder of a task that ends at the charger (tidy-up: cylinders(N) known) is delivered
// first wherever the robot is: the trip after it is the one to the charger anyway. Either only
// while the battery less the reserve (the worst drain) covers the way on to the charger. A cylinder
// knocked out by the storage area (knock-fetch's fetchingKnocked) is fetched first too.
// A task that ends at a known time (taskEnd) makes no trip while the battery covers what is left: a
// trip in the last minutes took what was left for the last cylinder (tidy-up: 83-156 s of 600).
// deliverOn(R2) (the agent's, optional): a delivery that went on first (deliveringFirst(T), T the
// pick's time, sweep's lastFound) keeps on while the battery less R2 covers the way: the reserve stands for a drain to come,
// and a drain during the delivery has come (tidy-up world 183: a drain of 113 J at 42 s, 0.66 m from
// the storage point, left 0.15 J too little over the reserve; the cylinder was carried to the charger
// 3.6 m away and back, delivered at 257-272 s, and 5 of 8 runs ended late)
@rechargeNotNeeded +lowBattery : not charging & .system_time(T) & batteryLasts(T).
@rechargeAfterDeliveryDecided
+lowBattery : deliverFirst(R) & deliverOn(_) & lastFound(T) & not deliveringFirst(T) & deliveryGoesOn(R)
    <- -+deliveringFirst(T).
@rechargeAfterDelivery
+lowBattery : deliverFirst(R) & deliveryGoesOn(R).
@deliveryKeptOn
+lowBattery : deliverOn(R) & lastFound(T) & deliveringFirst(T) & deliveryGoesOn(R).
@rechargeSuspend[atomic]
+lowBattery : episodeStart(X, Y, Z) & charger(Cx, Cz) & not charging & orientation(O)
    <- -lowFrom(_, _, _); +charging; !!rechargeTrip(X, Y, Z, O).
@rechargeTrip
+!rechargeTrip(X, Y, Z, O)
    <- mark(X, Y, Z); !suspendTask; ?battery(B); .print("Battery low! Level: ", B);
       !awaitChargerTurn; !goToCharger; stopAcquireDistance; !waitCharged; restartAcquireDistance; -atCharger;
       !chargerDone;
       .print("RECHARGED"); ?battery(B2); .print("Current battery level: ", B2);
       !backToTask(X, Y, Z, O).

// back to the marked point, and the task resumes there (the thesis'); an agent whose task goes on
// from anywhere (a search: tidy-up) believes resumeAtCharger and resumes where it charged
@resumeAtCharger +!backToTask(_, _, _, O) : resumeAtCharger <- stop; .print("Resuming from the charger"); !resumeTask(O).
@backToMarked
+!backToTask(X, Y, Z, O)
    <- -+targetPoint(X, Z); setUpTargetPoint(X, Y, Z); -+detours(0); !computeGap; !!balance; !!steer;
       !reachMarked; stop; .print("Previous pt reached"); !resumeTask(O).

// hooks for a robot that shares the charger (a team's skill: team-claims): its turn, then leave it
@chargerFree +!awaitChargerTurn.
@chargerLeft +!chargerDone.

// the trip to the charger, "charging" believed (the task stays suspended): also a robot's way to park
@goToCharger
+!goToCharger : charger(Cx, Cz)
    <- .succeed_goal(move(_)); -avoiding; -+detours(0);
       stop; setThreshold(0.03); -+targetPoint(Cx, Cz); setUpTargetPoint(Cx, 0, Cz);
       !computeGap; !!balance; !!steer; !reachCharger; +atCharger; stop; .drop_intention(balance); stop.

// the charger is tried again (the battery must be charged), the marked point is given up (the
// task resumes from where the robot is). The re-alignment is an intention of its own (!!balance), as
// on the first try: an obstacle met on the way drops every intention that has a balance goal
// (heading's detour), and dropped the whole trip with it; the robot then drove round the charger,
// "charging", for the rest of the run (team world 3, four robots: 430 s)
@reachCharger +!reachCharger : tripTimeout(T) <- .wait({+targetReached}, T).
@reachChargerAgain
-!reachCharger[error(E), error_msg(M)]
    <- println("Charger not reached yet (", E, " ", M, "): trying again"); !escape; !computeGap; !!balance; !reachCharger.
// chargeUntilLasts: a trip late in the task charged to 900 J, 20-30 s on the charger, where the
// time left needed a third of it
chargedEnough :- battery(B) & chargedLevel(C) & B >= C.
chargedEnough :- chargeUntilLasts(R) & .system_time(T) & taskEnd(End) & T < End & battery(B) & spendingPower(P)
    & B - R > P * (End - T) / 1000.
@waitChargedEnough +!waitCharged : chargeUntilLasts(_) <- .wait(chargedEnough, 120000).
@waitCharged +!waitCharged <- .wait({+charged}, 120000).
@notCharging
-!waitCharged : battery(B) & lowBatteryLevel(L) & B < L
    <- println("Not charging: back to the charger"); restartAcquireDistance; -atCharger;
       !computeGap; !!balance; !reachCharger; .drop_intention(balance); +atCharger; stop; stopAcquireDistance; !waitCharged.
@chargeEnded -!waitCharged : battery(B) <- println("Charging ended at ", B, " J").
// not in the thesis: a way back still under way when its time runs out (it came markedProgress m
// nearer the marked point on this try) is given another: a marked point given up leaves the
// low-battery episode open (the robot never came back), 0.2-1.2 m short after a slow way round
// (wide worlds)
@reachMarked
+!reachMarked : tripTimeout(T) & markedDistance(D)
    <- -+markedFrom(D); .wait({+targetReached}, T).
@reachMarkedAgain
-!reachMarked : markedFrom(D0) & markedDistance(D) & markedProgress(P) & D < D0 - P & targetPoint(Tx, Tz) & location(X, _, Z)
    <- println("Marked point not reached in time, still coming nearer (", D, " m): trying again");
       -markedTryFrom(_, _, _, _); +markedTryFrom(Tx, Tz, X, Z); !computeGap; !!balance; !reachMarked.
// markedByRoute: a try no markedProgress nearer in a straight line is given another when the way left along
// the route map (the middleware's routeLength, round the walls met) is markedProgress shorter than from
// where the try began (the charger, or where the last try ran out): a way back round an inner wall goes
// away from the marked point first, and was given up just through the wall's corridor (wide world 313)
markedTryStart(Tx, Tz, X, Z) :- markedTryFrom(Tx, Tz, X, Z).
markedTryStart(Tx, Tz, X, Z) :- not markedTryFrom(Tx, Tz, _, _) & charger(X, Z).
@reachMarkedAlongRoute
-!reachMarked : markedByRoute & targetPoint(Tx, Tz) & location(X, _, Z) & markedTryStart(Tx, Tz, X0, Z0)
    <- routeLength(X0, Z0, Tx, Tz, L0); routeLength(X, Z, Tx, Tz, L); !markedAlongRoute(L0, L, X, Z).
@markedNearerAlongRoute
+!markedAlongRoute(L0, L, X, Z) : markedProgress(P) & L < L0 - P & targetPoint(Tx, Tz)
    <- println("Marked point not reached in time, nearer along the route (", L, " m against ", L0, "): trying again");
       -markedTryFrom(_, _, _, _); +markedTryFrom(Tx, Tz, X, Z); !computeGap; !!balance; !reachMarked.
@markedNoNearerAlongRoute
+!markedAlongRoute(L0, L, _, _) <- println("Marked point not reached in time, no nearer along the route (", L, " m against ", L0, "): resuming from here").
@markedGivenUp
-!reachMarked[error(E), error_msg(M)]
    <- println("Marked point not reached in time (", E, " ", M, "): resuming from here").

@restore[atomic]
+!restoreOrientation(D)
    <- .print("Restoring"); -+desired(D); !balance; stop; .drop_intention(balance); .print("Restored"); .wait(500).
