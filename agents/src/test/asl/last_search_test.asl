// Skill tests of the search for the last cylinder (skills/last-search.asl, in tidy-up.asl): with one
// cylinder left, the sweep's next waypoint is the nearest floor the camera has not looked over (the
// middleware's unseenNext), and a waypoint already looked at gives way to the next at the sweep's step;
// with more left, the sweep keeps its lanes. Artifact operations are mocked (agents/README.md "Testing skills").
// Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/tidy-up.asl") }

arena(2.0, 2.0).
storagePoint(0.75, 0.75).
storageRadius(0.1).
charger(-0.75, 0.75).
cylinders(3).

mock_operation(unseenNext(_, _, _, _, _, _, -0.375, -0.625), ok).
mock_operation(_, ok).

// a search under way, nothing remembered, no look around due, Left cylinders still to store
+!searching_with(Left) <- !forget_calls; .abolish(seenCylinder(_, _)); .abolish(lookingAgain(_, _, _)); -picked(true);
    -+stored(3 - Left); -+location(0.1, 0, 0.2); -+orientation(0); -+lastLook(100000000000000); +searching;
    -+sweep([[0.75, -0.75], [-0.75, -0.75]]).

@[test]
+!test_with_two_left_the_sweep_keeps_its_lanes
    <- !searching_with(2); !nextWaypoint;
       !assert_true(waypoint(0.75, -0.75, _));
       !assert_false(mock_called(unseenNext(_, _, _, _, _, _, _, _)));
       -searching.

@[test]
+!test_with_one_left_the_next_waypoint_is_the_nearest_floor_not_looked_over
    <- !searching_with(1); !nextWaypoint;
       !assert_true(mock_called(unseenNext(0.1, 0.2, 0.9, 0.75, 0.75, _, _, _)));
       !assert_true(waypoint(-0.375, -0.625, _));
       -searching.

@[test]
+!test_with_one_left_a_waypoint_looked_at_gives_way_to_the_next
    <- !searching_with(1); -+waypoint(0.625, -0.875, 0); +mock_operation(viewSeen(0.625, -0.875, 0.9, 1), ok);
       !sweepStep;
       !assert_true(mock_called(viewSeen(0.625, -0.875, 0.9, _)));
       !assert_true(waypoint(-0.375, -0.625, _));
       -mock_operation(viewSeen(0.625, -0.875, 0.9, 1), ok); -searching.

@[test]
+!test_with_one_left_a_waypoint_not_looked_at_is_kept
    <- !searching_with(1); -+waypoint(0.625, -0.875, 0); +mock_operation(viewSeen(0.625, -0.875, 0.9, 0), ok);
       !sweepStep;
       !assert_true(waypoint(0.625, -0.875, _));
       !assert_false(mock_called(unseenNext(_, _, _, _, _, _, _, _)));
       -mock_operation(viewSeen(0.625, -0.875, 0.9, 0), ok); -searching.
