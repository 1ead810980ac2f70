// Skill test of recovery (skills/recovery.asl): the wait for an obstacle to clear is bounded and
// ends in an escape (back off, turn a random angle, go on); an obstacle still in sight when a move
// starts is avoided. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/recovery.asl") }

maxSpeed(100).

mock_operation(_, ok).

// avoidance (avoidance.asl or coverage.asl), as far as this skill needs it
+!avoid(D) <- +avoided(D).

@[test]
+!test_an_obstacle_already_gone_needs_no_escape
    <- -+avoidTimeout(300); -+escapeBack(100);                     // shorter than the skill's, for speed
       !forget_calls; +obstacle(false);
       !clear;
       !assert_false(mock_called(setSpeeds(_, _))).

@[test]
+!test_an_obstacle_that_clears_in_time_needs_no_escape
    <- !forget_calls; -obstacle(false); +obstacle(true);
       !!perceive_after(obstacle(false), 100);
       !clear;
       !assert_false(mock_called(setSpeeds(_, _))).

@[test]
+!test_an_obstacle_that_stays_leads_to_an_escape
    <- !forget_calls; -obstacle(false); -obstacle(true); +obstacle(true);
       .system_time(T0);
       !clear;
       .system_time(T1);
       !assert_between(T1 - T0, 300, 3700);                        // avoidTimeout (not 3 s), then the escape
       !assert_true(mock_called(setSpeeds(-50, -50)));               // backs off at half speed
       !assert_true(mock_called(setSpeeds(50, -50)) | mock_called(setSpeeds(-50, 50)));  // turns
       !assert_true(mock_called(forward)).                           // and goes on

@[test]
+!test_a_move_with_an_obstacle_in_sight_avoids_it
    <- !forget_calls; -avoided(_); +delta(-40);
       !move(0.3);
       !assert_true(avoiding);
       !assert_true(mock_called(stop));
       !assert_true(avoided(-40)).
