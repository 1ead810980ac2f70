// Skill tests of the right of way between teammates (skills/team-way.asl, in team-delivery.asl):
// the robot whose name comes later gives way to a teammate too close (backs off from one ahead),
// the earlier one goes on; a teammate standing in the storage area's queue is given way whatever
// its name. The agent under test is named team_way_test: khepera1 comes before it, zeta after it.
// Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(1.0, 1.0).
storagePoint(0.41, -0.41).
storageRadius(0.1).
charger(-0.38, 0.38).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(_, ok).

@[test]
+!test_the_later_name_backs_off_from_a_teammate_ahead
    <- !forget_calls; +location(0.1, 0, 0.2); +orientation(90); +storageQueue([]); +chargerQueue([]);
       !!perceive(robotAt(khepera1, 0.1, 0.3));          // 10 cm ahead, an earlier name
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(-40, -40)));
       !assert_false(givingWay);
       -robotAt(khepera1, _, _).

@[test]
+!test_the_earlier_name_goes_on
    <- !forget_calls;
       !!perceive(robotAt(zeta, 0.1, 0.3));              // 10 cm ahead, a later name
       .wait(300);
       !assert_false(mock_called(setSpeeds(_, _)));
       -robotAt(zeta, _, _);
       !!perceive(robotAt(zeta, 0.1, 0.5));              // 30 cm away: nobody gives way
       .wait(300);
       !assert_false(mock_called(setSpeeds(_, _)));
       -robotAt(zeta, _, _).

@[test]
+!test_a_teammate_standing_in_a_queue_is_given_way
    <- !forget_calls; -storageQueue(_); +storageQueue([khepera1, zeta]);
       !!perceive(robotAt(zeta, 0.1, 0.1));              // 10 cm behind, waiting for the storage area
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(40, 40)));     // moves on, away from it
       -robotAt(zeta, _, _); -storageQueue(_); +storageQueue([]).

@[test]
+!test_two_robots_in_a_queue_go_by_name
    <- !forget_calls; -storageQueue(_); +storageQueue([team_way_test, khepera1]);
       !!perceive(robotAt(zeta, 0.1, 0.3));              // not queued: it gives way to this robot
       .wait(300);
       !assert_false(mock_called(setSpeeds(_, _)));
       -robotAt(zeta, _, _);
       !!perceive(robotAt(khepera1, 0.1, 0.3));          // queued too, an earlier name: this robot gives way
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(-40, -40)));
       -robotAt(khepera1, _, _); -storageQueue(_); +storageQueue([]).
