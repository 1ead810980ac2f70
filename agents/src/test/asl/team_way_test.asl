// Skill tests of giving way (skills/team-way.asl, in team-delivery.asl): a robot without an
// errand stops a moment for a teammate near it whose name comes first, not for one whose name
// comes later, and never while it delivers. The teammates' names are chosen to sort before
// (aaa_...) and after (zzz_...) the tester agent's own. Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(1.0, 1.0).
storagePoint(0.41, -0.41).
storageRadius(0.1).
charger(-0.38, 0.38).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(computeAngle(_, _, _, _, 90), ok).
mock_operation(_, ok).

@[test]
+!test_a_robot_gives_way_to_a_teammate_near_whose_name_comes_first
    <- +orientation(90); +location(0.0, 0, 0.0); !forget_calls;
       !!perceive(robotAt(aaa_first, 0.1, 0.05));                  // 11 cm away
       !until(givingWay, 3000);
       !assert_true(givingWay);
       !assert_true(mock_called(stop));
       !until(not givingWay, 5000);
       !assert_false(givingWay).

@[test]
+!test_no_way_is_given_to_a_teammate_whose_name_comes_later_nor_while_delivering
    <- !forget_calls;
       !!perceive(robotAt(zzz_last, 0.1, 0.05));
       .wait(300);
       !assert_false(givingWay);
       +delivering;
       !!perceive(robotAt(aaa_second, 0.05, 0.05));
       .wait(300);
       !assert_false(givingWay);
       -delivering.
