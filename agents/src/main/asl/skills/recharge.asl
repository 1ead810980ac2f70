// Skill: recharge with suspend/resume (thesis Chapter 4 §4.1 and Appendix B). When the battery
// runs low (lowBattery) whatever runs is suspended (the coordination belief "charging"): the robot
// marks its position and orientation, goes to the charger, waits there for the charge, comes back
// to the marked point, restores its orientation, and the suspended task resumes (-charging).
// Parameters:
lowBatteryLevel(480).   // J: the middleware signals lowBattery under it
chargedLevel(900).      // J: and charged over it
tripTimeout(150000).    // ms for the trip to the charger or back (recovery, not in the thesis)
// Reads: charger(X, Z) (the world file); ray(R), storagePoint(X, Z) (delivery).
// Beliefs: charging, atCharger. Rules it extends: travelling, pickingOff, onErrand, halted.
// Needs: delivery (computeGap, balance, steer, the target point), recovery (!escape).
// Include it FIRST among the skills: its plans that suspend a task (+!reach, +!block, +!pick,
// +!go_ahead, +!move : charging ...) must come before the task's own plans for the same goals.
// Deviations from the listing: the listing waits 3 s at the charger (".wait(3000)"); with the
// world's 20 W charger that is 60 J, and the battery was low again within a minute. The robot
// stops, ignores its distance sensors (a wall next to the charger must not make it leave) and
// waits for the middleware's "charged" signal, two minutes at most. Charger and marked point are
// reached with a 3 cm threshold (the charger's radius is 6 cm); the storage point's threshold (ray)
// is restored afterwards. "!restoreOrientation(0)" restores the orientation marked when the battery
// went low.

travelling :- charging.
pickingOff :- charging.
onErrand :- charging.
halted :- atCharger.
setUpGoal(setUpRecharge).
forgetOnFall(charging).
forgetOnFall(atCharger).

@setUpRecharge
+!setUpRecharge : lowBatteryLevel(L) & chargedLevel(C) <- batteryLevels(L, C).

/* Suspending the task that runs */

// an approach that times out after the battery ran low sends no "stop", which would halt the
// robot on its way to the charger for good
@approachFailedCharging -!approach : charging <- .print("Reach lateral cylinder failed."); -+reachCylinder(false).
@reachSuspend +!reach : charging <- .wait({-charging}); .print("Resume cylinder reaching"); !reach.
@moveSuspend +!move(N) : charging <- .print("wait recharging"); .wait("-charging"); .print("after recharging"); !move(N).
@blockSuspend
+!block : charging
    <- .print("Blocking suspend, wait recharging."); open_grip; arm_up;
       .wait({-charging}); .print("Blocking resumed"); !block.
@pickSuspend
+!pick : charging
    <- .print("Picking suspend, wait recharging."); .wait({-charging}); .print("Picking resumed"); !pick.
@deliverSuspend
+!go_ahead : charging
    <- .print("Delivering suspend, wait recharging."); .wait({-charging}); .print("Delivering resumed"); !go_ahead.
// on the way to the charger the threshold is the charger's: only remember the storage's ray
@raiseRayCharging +!raiseRay : charging & threshold(T) & maxRay(Mx) <- T2 = math.min(T + 0.03, Mx); -+ray(T2).
@stuckAtCharger +stuck : atCharger.

/* Low battery: suspend, recharge, come back, resume (Chapter 4 §4.1) */

// Recovery, not in the thesis: the waits for the charger, the charge and the marked point are
// bounded (!reachCharger, !waitCharged, !reachMarked); the robot steers on the way (!!steer).
// "charging" first: lowBattery comes every control step while the battery is low, and those queued
// behind an atomic plan must find the robot charging already (else each one started a recharge)
@rechargeSuspend
+lowBattery : location(X, Y, Z) & charger(Cx, Cz) & not charging & orientation(O)
    <- +charging; mark; ?battery(B); .print("Battery low! Level: ", B);
       !awaitChargerTurn; !goToCharger; stopAcquireDistance; !waitCharged; restartAcquireDistance; -atCharger;
       !chargerDone;
       .print("RECHARGED"); ?battery(B2); .print("Current battery level: ", B2);
       -+targetPoint(X, Z); setUpTargetPoint(X, Y, Z); -+detours(0); !computeGap; !!balance; !!steer;
       !reachMarked; stop; .print("Previous pt reached");
       ?storagePoint(Tx, Tz); -+targetPoint(Tx, Tz); setUpTargetPoint(Tx, 0, Tz); ?ray(R); setThreshold(R);
       !restoreOrientation(O); -charging.

// hooks for a robot that shares the charger (a team's skill: team-claims): its turn, then leave it
@chargerFree +!awaitChargerTurn.
@chargerLeft +!chargerDone.

// the trip to the charger, "charging" believed (the task stays suspended): also a robot's way to park
@goToCharger
+!goToCharger : charger(Cx, Cz)
    <- .succeed_goal(move(_)); -avoiding; -+detours(0);
       stop; setThreshold(0.03); -+targetPoint(Cx, Cz); setUpTargetPoint(Cx, 0, Cz);
       !computeGap; !!balance; !!steer; !reachCharger; +atCharger; stop; .drop_intention(balance); stop.

@rechargeResume -charging : delivering <- .print("Restart delivering"); !computeGap; !balance; !!steer.

// the charger is tried again (the battery must be charged), the marked point is given up (the
// task resumes from where the robot is)
@reachCharger +!reachCharger : tripTimeout(T) <- .wait({+targetReached}, T).
@reachChargerAgain
-!reachCharger[error(E), error_msg(M)]
    <- println("Charger not reached yet (", E, " ", M, "): trying again"); !escape; !computeGap; !balance; !reachCharger.
@waitCharged +!waitCharged <- .wait({+charged}, 120000).
@notCharging
-!waitCharged : battery(B) & lowBatteryLevel(L) & B < L
    <- println("Not charging: back to the charger"); restartAcquireDistance; -atCharger;
       !computeGap; !balance; !reachCharger; +atCharger; stop; stopAcquireDistance; !waitCharged.
@chargeEnded -!waitCharged : battery(B) <- println("Charging ended at ", B, " J").
@reachMarked +!reachMarked : tripTimeout(T) <- .wait({+targetReached}, T).
@markedGivenUp
-!reachMarked[error(E), error_msg(M)]
    <- println("Marked point not reached in time (", E, " ", M, "): resuming from here").

@restore[atomic]
+!restoreOrientation(D)
    <- .print("Restoring"); -+desired(D); !balance; stop; .drop_intention(balance); .print("Restored"); .wait(500).
