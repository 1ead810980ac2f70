// Skill tests of where the teammates are (skills/team-places.asl, in team-delivery.asl): the
// robot publishes its place on the board, at most once per placeEvery; a teammate's published
// place makes teammateNear hold around it, the robot's own never. Run: jacabot test agents/src/test/asl
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
+!test_the_place_is_published_once_a_second_at_most
    <- !forget_calls; -+placeEvery(1000);                 // (a second: room for a loaded machine)
       !!perceive(location(0.1, 0, 0.2));
       !until(mock_called(at(0.1, 0.2)), 2000);
       !assert_true(mock_called(at(0.1, 0.2)));
       -location(_, _, _); !!perceive(location(0.11, 0, 0.2));   // at once: not again
       .wait(100);
       !assert_false(mock_called(at(0.11, 0.2)));
       .wait(1000);
       -location(_, _, _); !!perceive(location(0.12, 0, 0.2));   // a second later: again
       !until(mock_called(at(0.12, 0.2)), 2000);
       !assert_true(mock_called(at(0.12, 0.2))).

@[test]
+!test_a_teammate_is_near_its_published_place_and_the_robot_is_not_its_own_teammate
    <- .my_name(Me);
       +robotAt(Me, 0.5, 0.5); +robotAt(khepera9, -0.5, -0.5);
       !assert_true(teammateNear(-0.45, -0.5));
       !assert_false(teammateNear(-0.2, -0.5));
       !assert_false(teammateNear(0.5, 0.5)).
