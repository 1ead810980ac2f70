// Skill test of the turn in an arc (skills/arc-turn.asl with heading.asl): on the way, a heading a
// little off is taken in an arc, both wheels forward; a large turn, or one near the point headed
// for, is heading's turn on the spot. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/arc-turn.asl") }
{ include("../../main/asl/skills/heading.asl") }

maxSpeed(100).
location(0, 0, 0).
aim(1, 0).
targetPoint(1, 0).
travelling.
mock_operation(_, ok).

@[test]
+!test_a_small_turn_on_the_way_is_an_arc
    <- !forget_calls; -+orientation(70); -+desired(90);
       !!balance;
       !until(mock_called(setSpeeds(100, 30)), 2000);
       !assert_true(mock_called(setSpeeds(100, 30)));                // to the right: the left wheel outside
       !assert_false(mock_called(setSpeeds(25, -10)));               // not on the spot
       -+orientation(89); !until(not .intend(balance), 2000);
       !assert_true(mock_called(setSpeeds(100, 100))).               // straight on within arcDone

@[test]
+!test_a_large_turn_or_one_near_the_aim_is_on_the_spot
    <- !forget_calls; -+orientation(0); -+desired(90);
       !!balance; .wait(100);
       !assert_true(mock_called(setSpeeds(25, -10)));
       !assert_false(mock_called(setSpeeds(100, 30)));
       -+orientation(90); !until(not .intend(balance), 2000);
       !forget_calls; -+aim(0.1, 0); -+orientation(70);
       !!balance; .wait(100);
       !assert_true(mock_called(setSpeeds(25, -10)));
       !assert_false(mock_called(setSpeeds(100, 30)));
       -+orientation(90); !until(not .intend(balance), 2000); -+aim(1, 0).
