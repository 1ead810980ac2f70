// Skill: a recharge trip taken up again after a fall, not in the thesis. A cylinder knocked out of
// the gripper on the trip (the world's knocks) drops every desire, the trip with them, and forgets
// "charging" (delivery's @fallCylinder, suspension's forgetOnFall): the robot left the charger half
// charged, or stopped on its way back, and the low-battery episode stayed open (wide world 106, seed
// 2 with look points: knocked on the charger at 421 s, left it with 590 J). Here the fall is let
// through to delivery's plan, and then the trip goes on from where the robot is, to the same marked
// point: the whole trip if it fell before the way back, else the way back alone (the charger's
// "charged" is signalled once a low battery).
// The episode is the same: a low battery seen between the fall and the trip taken up again is no
// new episode's start (recharge-trip's lowFrom is forgotten).
// The fall is signalled again (-fallen: a fall believed, as in the skill tests, makes no new event).
// Beliefs: fellOnTrip(Stage, X, Y, Z, O) (between the fall and the trip taken up again).
// Needs: recharge-trip (!rechargeTrip, !backToTask), delivery (+fallen). Include it before
// recharge.asl: its +lowBattery plan must come before the one that starts a new trip.

@fallOnTrip[atomic]
+fallen : not fellOnTrip(_, _, _, _, _) & .intend(rechargeTrip(X, Y, Z, O))
    <- if (.intend(backToTask(_, _, _, _))) { +fellOnTrip(back, X, Y, Z, O) } else { +fellOnTrip(whole, X, Y, Z, O) };
       -fallen; +fallen; -fallen.

// the first of the fall's forgotten "charging" and the next low-battery signal takes the trip up
// (atomic: "charging" is believed again before any other event is considered)
@tripAgainCharging[atomic] -charging : fellOnTrip(S, X, Y, Z, O) <- !tripAgain(S, X, Y, Z, O).
@tripAgainLow[atomic] +lowBattery : fellOnTrip(S, X, Y, Z, O) <- !tripAgain(S, X, Y, Z, O).
@tripAgain
+!tripAgain(S, X, Y, Z, O)
    <- .abolish(fellOnTrip(_, _, _, _, _)); -lowFrom(_, _, _); +charging; println("Cylinder fallen on the recharge trip: the trip goes on");
       !!tripFrom(S, X, Y, Z, O).
@tripWhole +!tripFrom(whole, X, Y, Z, O) <- !rechargeTrip(X, Y, Z, O).
@tripBack +!tripFrom(back, X, Y, Z, O) <- !backToTask(X, Y, Z, O).
