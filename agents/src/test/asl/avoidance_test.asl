// Skill test of obstacle avoidance of the Khepera (skills/avoidance.asl): a front obstacle makes
// the robot back off and turn away from the obstacle's side (or around when it is central), a
// lateral one as a front one; random motion waits meanwhile; picking and travelling keep their own
// way round. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/avoidance.asl") }

maxSpeed(100).
mock_operation(_, ok).

// what the skill needs of recovery and far sight: the obstacle clears at once
+!clear <- +cleared.
+!goRound <- +wentRound.
// random motion (the last +!move plan, as random-walk.asl's)
+!move(N) <- +moved(N).

// a new obstacle percept (the previous one gone)
+!obstacle_ahead(D) <- -+delta(D); -obstacle(true); !!perceive(obstacle(true)).

@[test]
+!test_a_central_obstacle_makes_the_robot_back_off_and_turn_around
    <- !forget_calls; -cleared; !obstacle_ahead(0);
       !until(cleared & not avoiding, 2000);
       !assert_true(mock_called(stop));
       !assert_true(mock_called(backward));
       !assert_true(mock_called(turnAround));
       !assert_false(avoiding).

@[test]
+!test_an_obstacle_to_the_left_makes_the_robot_turn_right
    <- !forget_calls; -cleared; !obstacle_ahead(40);
       !until(cleared & not avoiding, 2000);
       !assert_true(mock_called(backward));
       !assert_true(mock_called(setSpeeds(50, -50)));
       !assert_false(mock_called(turnAround)).

@[test]
+!test_an_obstacle_to_the_right_makes_the_robot_turn_left
    <- !forget_calls; -cleared; !obstacle_ahead(-40);
       !until(cleared & not avoiding, 2000);
       !assert_true(mock_called(setSpeeds(-50, 50))).

@[test]
// as the thesis' listing (!avoid(-1)): the turn a front obstacle on the right gets
+!test_a_lateral_obstacle_on_the_left_is_avoided_turning_left
    <- !forget_calls; -cleared; !!perceive(lateralObstacle("left"));
       !until(cleared & not avoiding, 2000);
       !assert_true(mock_called(stop));
       !assert_true(mock_called(setSpeeds(-50, 50))).

@[test]
+!test_no_avoidance_while_picking
    <- !forget_calls; +picking; !obstacle_ahead(0);
       .wait(300); -picking;
       !assert_false(mock_called(stop));
       !assert_false(avoiding).

@[test]
+!test_random_motion_waits_while_avoiding
    <- -moved(_); +avoiding; !!move(0.4);
       .wait(200);
       !assert_false(moved(_));
       -avoiding;
       !until(moved(_), 2000);
       !assert_true(moved(0.4)).

@[test]
+!test_homing_goes_round_the_obstacle_after_avoiding_it
    <- !forget_calls; -cleared; +homing(0); !obstacle_ahead(0);
       !until(wentRound, 2000);
       -homing(_);
       !assert_true(wentRound).
