// Skill test of a recharge trip taken up again after a fall (skills/trip-after-fall.asl): a cylinder
// knocked out of the gripper on the trip (delivery's fall drops the trip and forgets "charging")
// starts the trip again towards the same marked point, the whole trip before the way back, the way
// back alone on it; a fall with no trip under way starts none. The trip and the fall are stand-ins
// (delivery's fall drops every desire, the tester's too).
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/trip-after-fall.asl") }

// recharge-trip's trip: to the charger until "chargedHere", then the way back until "backHere"
@tripStandIn +!rechargeTrip(X, Y, Z, O) <- +tripBegun(X, Z); .wait({+chargedHere}); !backToTask(X, Y, Z, O).
@backStandIn +!backToTask(X, _, Z, _) <- +backBegun(X, Z); .wait({+backHere}); -charging.
// delivery's fall: the trip dropped, "charging" forgotten
@fallStandIn +fallen <- .drop_intention(rechargeTrip(_, _, _, _)); .abolish(charging); +fallHandled.

@cleanUp
+!clean_up <- .drop_intention(rechargeTrip(_, _, _, _)); .drop_intention(tripFrom(_, _, _, _, _)); -charging; -fallen; -fallHandled;
              .abolish(tripBegun(_, _)); .abolish(backBegun(_, _)); -chargedHere; -backHere.

@[test]
+!test_a_fall_on_the_way_to_the_charger_starts_the_whole_trip_again
    <- +charging; !!rechargeTrip(0.3, 0, -0.1, 90);
       !until(tripBegun(0.3, -0.1), 2000); -tripBegun(_, _);
       !!perceive(fallen);
       !until(fallHandled & tripBegun(_, _), 2000);
       !assert_true(fallHandled);
       !assert_true(tripBegun(0.3, -0.1));                // to the charger again, the first mark kept
       !assert_true(charging);
       !assert_false(fellOnTrip(_, _, _, _, _));
       !clean_up.

@[test]
+!test_a_fall_on_the_way_back_takes_the_way_back_again
    <- +charging; !!rechargeTrip(0.3, 0, -0.1, 90);
       !until(tripBegun(_, _), 2000); !!perceive(chargedHere);
       !until(backBegun(_, _), 2000); -backBegun(_, _); -tripBegun(_, _);
       !!perceive(fallen);
       !until(fallHandled & backBegun(_, _), 2000);
       !assert_true(backBegun(0.3, -0.1));                // back to the first mark
       !assert_false(tripBegun(_, _));                    // not to the charger: it was charged
       !assert_true(charging);
       -chargedHere; !!perceive(backHere);
       !until(not charging, 2000);
       !assert_false(charging);                           // the task resumes
       !clean_up.

@[test]
+!test_a_fall_with_no_trip_under_way_starts_none
    <- !!perceive(fallen);
       !until(fallHandled, 2000); .wait(200);
       !assert_true(fallHandled);
       !assert_false(charging);
       !assert_false(tripBegun(_, _));
       !clean_up.
