// Skill test of the way back the robot came (skills/way-back.asl with way-round.asl and heading.asl):
// the way back from the charger heads for the trail's point; a trip heads for its target until a
// wall is met again, then takes the trail when it knows a way there (no boundary following), and
// follows the wall when it does not. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/way-back.asl") }
{ include("../../main/asl/skills/way-round.asl") }
{ include("../../main/asl/skills/heading.asl") }

maxSpeed(100).
arena(2, 2).
location(0, 0, 0).
orientation(0).
charger(0.8, -0.8).
targetPoint(0.9, 0.4).
leftSensor(0).
rightSensor(0).
travelling :- delivering.

// the trail's way to (0.9, 0.4) bends at (0.2, -0.3); none is known to (-0.5, 0.5);
// headings: 300 degrees to the bend, 24 to the target
mock_operation(trailTo(0.9, 0.4, 0.2, -0.3), ok).
mock_operation(trailTo(-0.5, 0.5, -0.5, 0.5), ok).
mock_operation(computeAngle(_, _, 0.2, -0.3, 300), ok).
mock_operation(computeAngle(_, _, 0.9, 0.4, 24), ok).
mock_operation(computeAngle(_, _, -0.5, 0.5, 135), ok).
mock_operation(_, ok).

@[test]
+!test_the_way_back_from_the_charger_takes_the_trail
    <- !forget_calls; +charging; !computeGap;
       !assert_true(mock_called(trailTo(0.9, 0.4, _, _)));
       !assert_true(aim(0.2, -0.3) & desired(300));
       -charging.

@[test]
+!test_a_trail_blocked_by_obstacles_gone_round_on_it_is_left
    <- !forget_calls; +charging; -+detours(12); !computeGap;
       !assert_false(mock_called(trailTo(_, _, _, _)));
       !assert_true(desired(24));
       -charging; -+detours(0).

@[test]
+!test_a_trip_heads_for_its_target_until_a_wall_is_met
    <- !forget_calls; +delivering; -+detours(0); !computeGap;
       !assert_false(mock_called(trailTo(_, _, _, _)));
       !assert_true(desired(24));
       -delivering.

@[test]
+!test_a_wall_met_again_takes_the_trail_it_knows_not_the_wall
    <- +delivering; -+detours(0); -+detours(1);
       +obstacle(true);
       !until(onTrail, 1000);
       !assert_true(onTrail & aim(0.2, -0.3));
       !assert_false(followingWall(_, _, _));
       -obstacle(true); -+detours(0);
       !until(not onTrail, 1000);
       !assert_false(onTrail);                  // a new trip: the target first again
       -delivering.

@[test]
+!test_a_wall_met_again_with_no_trail_there_is_followed
    <- -+targetPoint(-0.5, 0.5); +delivering; -+detours(0); -+detours(1);
       +obstacle(true);
       !until(followingWall(_, _, _), 1000);
       !assert_true(followingWall(_, _, _));
       !assert_false(onTrail);
       -delivering; -obstacle(true); -+targetPoint(0.9, 0.4);
       !until(not followingWall(_, _, _), 1000).
