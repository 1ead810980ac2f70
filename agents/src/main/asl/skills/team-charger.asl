// Skill: one charger for the team (thesis Chapter 6, multi-robot coordination; not in the thesis),
// the team's side of recharge's hooks (!awaitChargerTurn, !chargerDone). The charger's queue is
// ordered by need (the robot with the least energy first; the one on the charger keeps it).
// - A robot whose battery runs low while another robot has the charger books its place
//   (requestCharger(Energy)) and goes on with its task; its trip starts when its turn comes (it
//   heads the queue) or when its energy falls to its reserve, whichever is first. So robots
//   low at once do not stand in a line at the charger while one charges. The reserve grows with
//   the way to the charger and the robots ahead in the queue (chargerReserveNow): a fixed one ran
//   a battery empty when the trip was long and the queue slow.
// - The queue ranks the robots waiting at the charger (awaitCharger) before those that booked
//   from afar and have not arrived (the charger's queue does it): a robot at the charger does not
//   wait while a needier one still travels.
// - On its trip a robot queues by need (requestCharger(Energy)), goes near the charger (within
//   chargerQueueRadius, per axis) and there waits its turn (awaitCharger), standing still out of
//   the way of the robot on the charger, then goes on to it. The robot whose turn it is but that
//   does not reach the charger within chargerTurnLimit, or comes no nearer it for chargerProgressTime
//   while another robot waits at the charger, lets the next one go first (yieldCharger).
// - A robot on the charger while another is queued leaves it once at chargerShare and the battery
//   covers the run's time left (taskEnd; a robot charges to recharge-trip's chargedLevel when nobody
//   waits or the time left needs it), and already at chargerShareFloor when a
//   robot waiting at the charger has less energy than it (chargerWaiting: the waiting ones'
//   energies). A robot recharged leaves the queue once it
//   is chargerLeaveDistance from the charger, so that the next one does not come while it leaves.
// - Not in the thesis: with teammates, a recharged robot drives off at once (a quick turn, then
//   travel speed) away from the charger's walls and from the teammates near it, leaves the queue
//   chargerClearDistance from the charger and drives on out of chargerLeaveDistance before its
//   task resumes, without turning back to the heading it had when its battery went low (resumeTask:
//   it goes on from the charger). It turned 9 s on the charger to that heading, then its task
//   drove it into the robots waiting there; the charger stood empty 20 s at each change (team world
//   96, four robots: three robots low at once, the third waited 73 s).
// Parameters:
chargerQueueRadius(0.3).     // m (per axis, the middleware's target test) where a robot queues
chargerTurnLimit(40000).     // ms the robot whose turn it is may take to reach the charger ...
chargerProgressTime(12000).  // ... or to come chargerProgressStep nearer it while another robot waits there
chargerProgressStep(0.05).   // m
chargerLeaveDistance(0.3).   // m from the charger where a recharged robot leaves the queue (holding its turn,
                             // it has the right of way through the robots waiting there)
chargerLeaveTimeout(40).     // quarter-seconds a recharged robot may take to go that far
chargerReserve(100).         // J: a robot booked for the charger works on above it, plus the way
                             // and the queue ahead (below)
tripDetours(1.5).            // the energy per metre to the charger, as a share of the straight
                             // line's (recharge-trip's wayEnergy): half as much again for the detours
queueEnergy(25).             // J per robot ahead in the queue (waits, and the last metres to the charger)
chargerShare(750).           // J: a robot on the charger leaves at this level while another is queued
chargerShareFloor(600).      // J: and at this one when a robot waiting at the charger is needier
chargerOffReach(0.4).        // m: with teammates, a recharged robot drives off towards a point this far ...
chargerClearDistance(0.15).  // m: ... and leaves the queue this far from the charger (it drives on out of
                             // chargerLeaveDistance, or for chargerOffTime)
chargerOffTime(12000).       // ms the drive off may take
teamMeanPower(2.0).         // W: with teammates, the power recharge-trip's taskEnd sums assume (meanPower) ...
teamChargeReserve(100).     // J: ... and a charge ends once the battery less this covers the time left
                            // at that power (chargeUntilLasts)
chargerNearTeammate(0.5).    // m from the charger: a teammate this near is driven away from
// Beliefs: waitingCharger, chargerWaitFrom(T), chargerWaitOver(T), yieldedCharger, chargerBooked, leavingCharger. Rules it extends: halted, waitingTurn.
// Reads: charger(X, Z) (the world), charging, atCharger, wayEnergy, batteryLasts (recharge-trip; taskEnd(T), the
// run's end, told by the team's runner), chargerQueue(L),
// chargerWaiting(L) (the charger), location, battery, insideArea (delivery), robotAt(A, X, Z) (team-places).
// Needs: team-way (!standStill), recharge-trip (its hooks; !reachCharger), heading (computeGap, balance, steer), recovery
// (!escape), the charger's queue focused (team-claims). Include it before recharge: its plans
// for -!reachCharger and the obstacles while waiting come first.

halted :- waitingCharger.
waitingTurn :- waitingCharger.
chargerBusy :- .my_name(Me) & chargerQueue([H | _]) & H \== Me.
chargerDistance(D) :- charger(Cx, Cz) & distanceTo(Cx, Cz, D).
nearCharger(W) :- location(X, _, Z) & charger(Cx, Cz) & (X - Cx) * (X - Cx) < W * W & (Z - Cz) * (Z - Cz) < W * W.
// the energy a booked robot keeps for its trip: the reserve, the way (as the crow flies) and the
// robots ahead of it in the queue
tripEnergy(E) :- wayEnergy(W) & tripDetours(F) & E = W * F.
chargerReserveNow(R) :- chargerReserve(R0) & tripEnergy(Em) & queueEnergy(Eq) & location(X, _, Z) & charger(Cx, Cz)
    & .my_name(Me) & chargerQueue(L) & queuedAhead(L, Me, N)
    & R = R0 + Em * math.sqrt((X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz)) + Eq * N.
queuedAhead([], _, 0).
queuedAhead([Me | _], Me, 0).
queuedAhead([A | T], Me, N) :- A \== Me & queuedAhead(T, Me, N0) & N = N0 + 1.
neediestWaiting(E) :- chargerWaiting([E0 | T]) & .min([E0 | T], E).
withTeammates :- robotAt(A, _, _) & not .my_name(A).
// with teammates (not in the thesis): the time left is reckoned at teamMeanPower, not the wheels at
// full speed all along, and a charge ends once it covers the time left (as tidy-up's agent). Off the
// charger two robots drew 1.54-1.61 W (team worlds 5 and 40); each made one trip and ended its run
// with 200-680 J, charged in vain. A lone robot runs as before (not tried alone)
meanPower(P) :- withTeammates & teamMeanPower(P).
chargeUntilLasts(R) :- withTeammates & teamChargeReserve(R).
lastsToTheEnd :- .system_time(T) & batteryLasts(T).
shortOfTheEnd :- taskEnd(_) & not lastsToTheEnd.
// the drive off the charger and the last metres onto it turn quickly (heading's balance)
quickTurn(V, A) :- charging & withTeammates & chargerLeaveDistance(D) & nearCharger(D) & quickTurnAt(V, A).
quickTurn(V, A) :- leavingCharger & quickTurnAt(V, A).
chargerCleared :- chargerClearDistance(C) & chargerDistance(D) & D >= C.
// the sum of the unit vectors from the teammates in L (p(X, Z)) to (X, Z)
awaySum([], _, _, 0, 0).
awaySum([p(Rx, Rz) | T], X, Z, Ax, Az) :- awaySum(T, X, Z, Ax0, Az0)
    & D = math.sqrt((X - Rx) * (X - Rx) + (Z - Rz) * (Z - Rz)) & D > 0.001 & Ax = Ax0 + (X - Rx) / D & Az = Az0 + (Z - Rz) / D.
awaySum([p(Rx, Rz) | T], X, Z, Ax, Az) :- awaySum(T, X, Z, Ax, Az) & (X - Rx) * (X - Rx) + (Z - Rz) * (Z - Rz) <= 0.000001.
// the way off the charger (a unit vector): towards the arena's centre and away from the teammates
// (A), kept off the walls (team-storage's offWalls); else square to the centre's way, on the side
// away from the teammates; else straight to the centre
centreWay(Cx, Cz, Ux, Uz) :- N = math.sqrt(Cx * Cx + Cz * Cz) & N > 0.001 & Ux = -Cx / N & Uz = -Cz / N.
centreWay(Cx, Cz, 1, 0) :- Cx * Cx + Cz * Cz <= 0.000001.
chargerWayOff(X, Z, Ax, Az, Wx, Wz) :- charger(Cx, Cz) & centreWay(Cx, Cz, Ux, Uz)
    & wayOffWalls(X, Z, Ux + Ax, Uz + Az, Wx, Wz).
chargerWayOff(X, Z, Ax, Az, Wx, Wz) :- charger(Cx, Cz) & centreWay(Cx, Cz, Ux, Uz)
    & squareWay(Ux, Uz, Ax, Az, Px, Pz) & wayOffWalls(X, Z, Px, Pz, Wx, Wz).
chargerWayOff(_, _, _, _, Ux, Uz) :- charger(Cx, Cz) & centreWay(Cx, Cz, Ux, Uz).
// the way (Vx, Vz) from (X, Z) kept off the walls, as a unit vector, while at least 0.3 of it is left
wayOffWalls(X, Z, Vx, Vz, Wx, Wz) :- offWalls(X, Z, Vx, Vz, Fx, Fz)
    & N = math.sqrt(Fx * Fx + Fz * Fz) & N >= 0.3 & Wx = Fx / N & Wz = Fz / N.
squareWay(Ux, Uz, Ax, Az, Px, Pz) :- Uz * Ax - Ux * Az >= 0 & Px = Uz & Pz = -Ux.
squareWay(Ux, Uz, Ax, Az, Px, Pz) :- Uz * Ax - Ux * Az < 0 & Px = -Uz & Pz = Ux.

// a low battery while another robot has its turn: the place is booked, the task goes on (the
// middleware signals lowBattery every control step while the battery is low: these two plans come
// before recharge-trip's, which starts the trip once neither applies)
@bookCharger[atomic]
+lowBattery : not charging & not chargerBooked & chargerBusy & battery(B) & chargerReserveNow(R) & B > R & not lastsToTheEnd
    <- +chargerBooked; requestCharger(B); .print("The charger is busy: booked at ", B, " J, working on").
// the battery covers the run's time left (taskEnd: recharge-trip then makes no trip): a place
// booked is given back, else the robot headed the queue without coming and its teammates booked
// and worked on behind it until their reserve
@bookingNotNeeded[atomic]
+lowBattery : chargerBooked & not charging & lastsToTheEnd <- -chargerBooked; leaveCharger; .print("The battery lasts: booking given back").
@workWhileBooked +lowBattery : not charging & chargerBooked & chargerBusy & battery(B) & chargerReserveNow(R) & B > R.
// a low battery in the storage area (a cylinder being put down, or the robot turning out after it):
// the area is left first, seconds away, while the battery is above the reserve. A trip begun
// there kept the cylinder and the area's beliefs (insideArea: no turn asked, no way given, no
// progress watched) on the way to the charger and back: team world 45, four robots, seed 1, a robot
// carried its cylinder from 186 s to 527 s and put it down beside the teammate whose turn it was,
// 15 s of contact. With teammates only: a robot alone runs as before (tried on teams only)
@storageAreaFirst +lowBattery : insideArea & not charging & withTeammates & battery(B) & chargerReserve(R) & B > R.

@awaitChargerTurn
+!awaitChargerTurn : chargerQueueRadius(W) & battery(B)
    <- -chargerBooked; requestCharger(B); !approachCharger(W); stop; !queueForCharger; .print("The charger is mine");
       !!watchChargerTurn.

@nearChargerAlready +!approachCharger(W) : nearCharger(W).
@approachCharger
+!approachCharger(W) : charger(Cx, Cz)
    <- .succeed_goal(move(_)); -avoiding; -+detours(0); stop; setThreshold(W);
       -+targetPoint(Cx, Cz); setUpTargetPoint(Cx, 0, Cz); !computeGap; !!balance; !!steer;
       !reachCharger; stop; .drop_intention(balance); stop.

// at the charger: its need now, then it waits as a robot that has arrived (before the booked ones)
@queueForCharger
+!queueForCharger : battery(B)
    <- +waitingCharger; !standStill; requestCharger(B); .print("Waiting for the charger"); !markChargerWait; awaitCharger; -waitingCharger;
       !markChargerWaitOver.
@queueForChargerNoReading
+!queueForCharger
    <- +waitingCharger; !standStill; .print("Waiting for the charger"); !markChargerWait; awaitCharger; -waitingCharger;
       !markChargerWaitOver.
// a wait of a second or more is marked (its end), for the no-progress signal that follows it (below)
@markChargerWait +!markChargerWait : .system_time(Now) <- -+chargerWaitFrom(Now).
@markChargerWaitOver
+!markChargerWaitOver : chargerWaitFrom(T) & .system_time(Now) & Now - T >= 1000 <- -+chargerWaitOver(Now).
@chargerWaitBrief +!markChargerWaitOver.
@queueForChargerFailed -!queueForCharger <- -waitingCharger.

// the turn given to a robot that does not reach the charger in time goes to the next one
// ... and so does the one that has come no nearer the charger by chargerProgressStep for
// chargerProgressTime while a robot waits at the charger: a turn held the whole chargerTurnLimit by
// a robot boxed in beside the charger kept the ones waiting there for 80 s (team world 3, four robots)
@watchChargerTurn
+!watchChargerTurn : chargerTurnLimit(T) & .system_time(Now) & chargerDistance(D) <- !watchChargerTurn(Now + T, D, Now).
@watchChargerTurnBlind +!watchChargerTurn : chargerTurnLimit(T) <- .wait(T); !checkChargerTurn.
@chargerTurnUsed +!watchChargerTurn(_, _, _) : atCharger | not charging.
@chargerTurnNearer
+!watchChargerTurn(Until, Best, _) : chargerDistance(D) & chargerProgressStep(S) & D < Best - S & .system_time(Now)
    <- !watchChargerTurn(Until, D, Now).
@chargerTurnOverdue +!watchChargerTurn(Until, _, _) : .system_time(Now) & Now >= Until <- !checkChargerTurn.
@chargerTurnStalled
+!watchChargerTurn(_, _, Since) : chargerWaiting([_ | _]) & chargerProgressTime(P) & .system_time(Now) & Now - Since >= P
    <- !checkChargerTurn.
@chargerTurnWatched +!watchChargerTurn(Until, Best, Since) <- .wait(500); !watchChargerTurn(Until, Best, Since).
@yieldChargerTurn
+!checkChargerTurn : charging & not atCharger & .intend(reachCharger) & .my_name(Me) & chargerQueue([Me, _ | _])
    <- .print("Charger not reached in time: the next robot goes first"); +yieldedCharger; yieldCharger;
       .fail_goal(reachCharger).
@keepChargerTurn +!checkChargerTurn.
@chargerTurnYielded
-!reachCharger : yieldedCharger
    <- -yieldedCharger; stop; !queueForCharger; .print("The charger is mine again"); !!watchChargerTurn;
       !escape; !computeGap; !!balance; !reachCharger.

// on the charger, a detour begun on the way there is over: it went on (forward, re-align, cruise)
// and drove the robot off the charger mid-charge, its turn held, until its battery ran empty
// (world 5, four robots)
@detourOverAtCharger +atCharger : .intend(detour(_)) <- .drop_intention(detour(_)); -avoiding; stop.

// another robot is queued: the charge is shared (the trip goes on as when charged), once the
// battery covers the run's time left (taskEnd known): a robot that left at chargerShare ran low a
// second time before the end, another trip of a minute or more on the charger's approach (the one
// robot, charged to chargedLevel, skipped its second trip late in the run; four robots not)
@shareCharger
+battery(B) : atCharger & chargerShare(S) & B >= S & .my_name(Me) & chargerQueue([Me, _ | _]) & .intend(waitCharged)
              & not shortOfTheEnd
    <- .print("Charged to ", B, " J: the next robot's turn"); .succeed_goal(waitCharged).

// a robot waiting at the charger is needier: it goes first, once this one has a working margin
@shareChargerNeedier
+battery(B) : atCharger & chargerShareFloor(S) & B >= S & neediestWaiting(E) & E < B & .my_name(Me)
              & chargerQueue([Me, _ | _]) & .intend(waitCharged)
    <- .print("Charged to ", B, " J: a needier robot waits (", E, " J)"); .succeed_goal(waitCharged).

// with teammates: the drive off (above), the queue left on the way
@driveOffCharger
+!chargerDone : withTeammates & location(X, _, Z) & charger(Cx, Cz) & .my_name(Me) & chargerNearTeammate(Q)
                & chargerOffReach(R) & chargerOffTime(T) & .system_time(Now)
    <- .findall(p(Rx, Rz), robotAt(A, Rx, Rz) & A \== Me & (Rx - Cx) * (Rx - Cx) + (Rz - Cz) * (Rz - Cz) < Q * Q, Near);
       ?awaySum(Near, X, Z, Ax, Az); ?chargerWayOff(X, Z, Ax, Az, Wx, Wz);
       +leavingCharger; -avoiding; -+detours(0); stop;
       -+targetPoint(X + R * Wx, Z + R * Wz); setUpTargetPoint(X + R * Wx, 0, Z + R * Wz);
       !computeGap; !!balance; !!steer;
       !driveOffClear(Now + T); leaveCharger;
       !driveOffOut(Now + T); stop; .drop_intention(balance); stop; -leavingCharger.
@leaveChargerQueue +!chargerDone : chargerLeaveTimeout(N) <- !!leaveChargerAway(N).
@driveOffClearOn +!driveOffClear(Until) : not chargerCleared & .system_time(Now) & Now < Until <- .wait(100); !driveOffClear(Until).
@driveOffCleared +!driveOffClear(_).
@driveOffOutOn
+!driveOffOut(Until) : chargerLeaveDistance(D) & nearCharger(D) & .system_time(Now) & Now < Until <- .wait(100); !driveOffOut(Until).
@driveOffOutDone +!driveOffOut(_).
@driveOffFailed -!chargerDone : leavingCharger <- -leavingCharger; leaveCharger.
// with teammates the task goes on from the charger as it faces (the drive off turned it away from
// the charger): the heading marked when the battery went low, far from here, is no use
@resumeOffCharger +!resumeTask(_) : withTeammates & resumeAtCharger <- !restoreTarget; -charging.
@leaveChargerAway
+!leaveChargerAway(N) : N > 0 & chargerLeaveDistance(D) & nearCharger(D) <- .wait(250); !leaveChargerAway(N - 1).
@leaveChargerNow +!leaveChargerAway(_) <- leaveCharger.
// a recharge given up (a fallen cylinder drops every desire and forgets "charging") leaves the
// queue too, else its robot held the charger for the rest of the run; with a cylinder being
// delivered, recharge's own plan for -charging resumes the delivery (the queue is left already).
// A robot recharged that goes on from the charger (resumeAtCharger) ends "charging" there: it
// leaves the queue once away (leaveChargerAway), not while it still sits on the charger.
@leaveChargerOnGiveUp
-charging : not delivering & not .intend(leaveChargerAway(_)) <- -waitingCharger; -chargerBooked; leaveCharger.

// while waiting for its turn the robot stands still
@obstacleWhileWaitingCharger +obstacle(true) : waitingCharger.
@lateralWhileWaitingCharger +lateralObstacle(_) : waitingCharger.
@stuckWhileWaitingCharger +stuck : waitingCharger.
// the middleware's progress windows ran on while the robot stood waiting: the first no-progress
// signal within the short window after the wait is the wait's, not the way's (team world 399, four
// robots, seed 1: the robot whose turn had come escaped 0.44 s later, backing away and re-aligning
// for 7 s, and reached the charger 24 s after its turn while two robots waited there)
@stuckFromTheChargerWait
+stuck : chargerWaitOver(T) & stuckWindows(W, _, _, _) & .system_time(Now) & Now - T < W <- -chargerWaitOver(T).
