// Skill test of random motion (skills/random-walk.asl): the random number chooses a straight
// stretch, a turn left or a turn right; the straight stretches run at legSpeed when the agent
// gives one. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/random-walk.asl") }

mock_operation(_, ok).

@[test]
+!test_low_number_goes_straight_forward
    <- !forget_calls; !!move(0.2);
       !until(mock_called(forward), 2000);
       .drop_desire(move(_));
       !assert_true(mock_called(forward));
       !assert_false(mock_called(turnLeft) | mock_called(turnRight)).

@[test]
+!test_middle_number_turns_left_then_goes_straight
    <- !forget_calls; !!move(0.6);
       !until(mock_called(turnLeft), 2000);
       .drop_desire(move(_));
       !assert_true(mock_called(turnLeft));
       !assert_false(mock_called(turnRight)).

@[test]
+!test_high_number_turns_right
    <- !forget_calls; !!move(0.9);
       !until(mock_called(turnRight), 2000);
       .drop_desire(move(_));
       !assert_true(mock_called(turnRight));
       !assert_false(mock_called(turnLeft)).

@[test]
+!test_straight_stretch_at_the_agents_leg_speed
    <- !forget_calls; +legSpeed(70); !!move(0.1);
       !until(mock_called(setSpeeds(_, _)), 2000);
       .drop_desire(move(_)); -legSpeed(70);
       !assert_true(mock_called(setSpeeds(70, 70)));
       !assert_false(mock_called(forward)).
