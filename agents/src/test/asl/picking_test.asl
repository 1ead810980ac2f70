// Skill test of picking a red cylinder up (skills/picking.asl): a cylinder ahead is caught and
// lifted, each step checked within its time limit, and then handed on (!go_ahead); a lateral one
// is turned to and approached first; none is taken while pickingOff holds; a missed catch or an
// arm that does not rise lets the cylinder go. The operations are mocked (agents/README.md
// "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/picking.asl") }

maxSpeed(100).
mock_operation(_, ok).

// what the agent does with the cylinder picked (delivery's), and recovery's escape
+!go_ahead : picked(true) <- +handedOn; -picking.
+!escape <- +escaped.
// random motion (the last +!move plan)
+!move(N) <- +moved(N).

@[test]
+!test_a_cylinder_ahead_is_caught_lifted_and_handed_on
    <- !forget_calls; !!perceive(cylinderDetected);
       !until(mock_called(catching), 2000);
       !assert_true(picking);
       !assert_true(mock_called(stop));
       !!perceive(caught(true));
       !until(mock_called(arm_up), 2000);
       !assert_true(mock_called(arm_up));
       !!perceive(picked(true));
       !until(handedOn, 2000);
       !assert_true(handedOn);
       -cylinderDetected; -caught(true); -picked(true).

@[test]
+!test_a_lateral_cylinder_is_turned_to_and_approached
    <- !forget_calls; -handedOn; !!perceive(cylinderLeft);
       !until(mock_called(setSpeeds(0, 10)), 2000);
       !assert_true(reachCylinder(true));                             // random motion waits
       !!perceive(cylinderBeyond);                                    // centred, farther
       !until(mock_called(setSpeeds(20, 20)), 2000);
       !assert_true(mock_called(setSpeeds(20, 20)));                  // the slow approach
       !!perceive(cylinderDetected);
       !until(mock_called(catching), 2000);
       !assert_true(mock_called(catching));
       !assert_true(reachCylinder(false));
       // the catch itself: the first test
       .drop_desire(block); -picking;
       -cylinderLeft; -cylinderBeyond; -cylinderDetected.

@[test]
+!test_no_cylinder_is_taken_while_picking_is_off
    <- !forget_calls; +pickingOff; !!perceive(cylinderDetected); !!perceive(cylinderRight);
       .wait(300); -pickingOff; -cylinderDetected; -cylinderRight;
       !assert_false(picking);
       !assert_false(mock_called(catching));
       !assert_false(mock_called(setSpeeds(10, 0))).

// a lateral reach whose cylinder comes in front once picking is off (a low battery meanwhile): the
// reach ends, the cylinder is not taken, and moves no longer wait for it
@[test]
+!test_a_reach_whose_cylinder_comes_in_front_while_picking_is_off_ends
    <- !forget_calls; -moved(_); !!perceive(cylinderLeft);
       !until(mock_called(setSpeeds(0, 10)), 2000);
       !!perceive(cylinderBeyond);
       !until(mock_called(setSpeeds(20, 20)), 2000);
       +pickingOff; !!perceive(cylinderDetected);
       !until(reachCylinder(false), 2000);
       !assert_true(reachCylinder(false));
       !assert_false(picking);
       !assert_false(mock_called(catching));
       !!move(0.4); !until(moved(_), 2000);
       !assert_true(moved(0.4));
       -pickingOff; -cylinderLeft; -cylinderBeyond; -cylinderDetected.

@[test]
+!test_a_missed_catch_lets_go_and_turns_away
    <- !forget_calls; +picking; -caught(_);
       !pick;
       !assert_true(mock_called(open_grip));
       !assert_true(mock_called(turnAround));
       !assert_false(picking);
       !assert_false(mock_called(arm_up) & not mock_called(open_grip)).

@[test]
+!test_an_arm_that_does_not_rise_gives_the_cylinder_up
    <- !forget_calls; -escaped; +picking; +caught(true);
       !pick;                                                         // picked(true) never comes
       -caught(true);
       !assert_true(mock_called(arm_up));
       !assert_true(mock_called(open_grip));
       !assert_true(escaped);
       !assert_false(picking | avoiding).

@[test]
+!test_random_motion_waits_while_picking
    <- -moved(_); +picking; !!move(0.3);
       .wait(200);
       !assert_false(moved(_));
       -picking;
       !until(moved(_), 2000);
       !assert_true(moved(0.3)).
