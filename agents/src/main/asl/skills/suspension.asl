// Skill: the task's side of suspend/resume (thesis Chapter 4 §4.1 and Appendix B). While
// "charging" is believed the task is suspended: a move, a reach, a block, a pick or a delivery
// that starts waits for -charging and then goes on; no cylinder is taken and the storage area is
// not the robot's business (pickingOff, onErrand). When charging ends, a delivery under way takes
// up its heading again. Who sets and ends "charging": recharge-trip.asl in the same agent
// (recharge.asl), or the energy agent's request (task-agent.asl).
// Reads: storagePoint(X, Z) (the world), ray(R) (delivery).
// Needs: delivery (computeGap, balance, steer). Include it FIRST among the task's skills: its plans
// that suspend a task (+!reach, +!block, +!pick, +!go_ahead, +!move : charging ...) must come
// before the task's own plans for the same goals.

pickingOff :- charging.
onErrand :- charging.
forgetOnFall(charging).

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

// before resuming: the storage point is the target again, with the storage's threshold
@restoreTarget
+!restoreTarget <- ?storagePoint(Tx, Tz); -+targetPoint(Tx, Tz); setUpTargetPoint(Tx, 0, Tz); ?ray(R); setThreshold(R).

@rechargeResume -charging : delivering <- .print("Restart delivering"); !computeGap; !balance; !!steer.
