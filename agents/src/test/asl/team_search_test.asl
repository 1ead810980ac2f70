// Skill tests of the search the team shares (skills/team-search.asl, in team-delivery.asl): with
// teammates, the sweep's next waypoint is the search map's next point, a point that moved on (its
// cell seen by someone) is headed for at once, the floor a robot looks over while it may take a
// cylinder is marked on the map, and the sweep starts sooner; alone, the robot keeps the sweep's
// lanes and marks nothing; "avoiding" left behind by an avoidance cut off ends in an escape.
// Artifact operations are mocked (see agents/README.md "Testing skills").
// Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(2.0, 2.0).
storagePoint(0.75, 0.75).
storageRadius(0.1).
charger(-0.75, 0.75).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(searchFrom(_, _, 0.375, -0.625), ok).
mock_operation(_, ok).

+!alone <- .abolish(robotAt(_, _, _)).
+!with_a_teammate <- .abolish(robotAt(_, _, _)); +robotAt(khepera9, -0.5, -0.5).

@[test]
+!test_alone_the_sweep_keeps_its_lanes_and_marks_nothing
    <- !alone; !forget_calls; -+location(0, 0, 0); -+orientation(0); -picked(true);
       -+sweep([[0.75, -0.75], [-0.75, -0.75]]);
       !nextWaypoint;
       !assert_true(waypoint(0.75, -0.75, _));
       !assert_false(mock_called(searchFrom(_, _, _, _)));
       !lookedFrom(0, 0);
       !assert_false(mock_called(looked(_, _, _, _)));
       !assert_true(sweepDelay(45000)).

@[test]
+!test_with_a_teammate_the_next_waypoint_is_the_maps_next_point
    <- !with_a_teammate; !forget_calls; -+location(0.1, 0, 0.2); -+orientation(0);
       -+sweep([[0.75, -0.75], [-0.75, -0.75]]);
       !nextWaypoint;
       !assert_true(mock_called(searchFrom(0.1, 0.2, _, _)));
       !assert_true(waypoint(0.375, -0.625, _));
       !assert_true(closest(1000));
       !assert_true(sweepDelay(5000)).

@[test]
+!test_a_point_moved_on_is_headed_for_and_one_reached_gives_the_next
    <- !with_a_teammate; !forget_calls; -+location(0.5, 0, 0.5); -+orientation(0); .my_name(Me);
       -+waypoint(-0.625, 0.125, 0); +searchPoint(Me, 0.875, -0.125);
       -+lastLook(100000000000000);                // no look around due
       !sweepStep;
       !assert_true(waypoint(0.875, -0.125, _));
       -searchPoint(Me, 0.875, -0.125);
       !forget_calls; -+waypoint(0.52, 0.5, 0);     // within 0.1 m
       !sweepStep;
       !assert_true(mock_called(searchFrom(0.5, 0.5, _, _)));
       !assert_true(waypoint(0.375, -0.625, _)).

@[test]
+!test_the_floor_looked_over_is_marked_unless_the_robot_carries_a_cylinder
    <- !with_a_teammate; !forget_calls; -+orientation(30); -picked(true); -charging; -searching;
       !lookedFrom(0.1, 0.2);
       !assert_true(mock_called(looked(0.1, 0.2, 30, false)));
       +searching; !lookedFrom(0.2, 0.2);
       !assert_true(mock_called(looked(0.2, 0.2, 30, true)));
       -searching; +picked(true); !forget_calls;
       !lookedFrom(0.3, 0.2);
       !assert_false(mock_called(looked(_, _, _, _)));
       -picked(true).

// an avoidance cut off (its move ended by a cylinder's reach) left "avoiding" behind: no progress
// then is an escape and the map's next point, and "avoiding" goes (without it the robot stood still)
@[test]
+!test_no_progress_with_avoiding_left_behind_means_an_escape
    <- !with_a_teammate; !forget_calls; -+location(0.1, 0, 0.2); -+orientation(0);
       -picking; -insideArea; -atCharger; +searching; +avoiding;
       !!perceive(stuck);
       !until(not avoiding, 6000);
       -stuck;
       !assert_false(avoiding);
       !assert_true(mock_called(searchFrom(0.1, 0.2, _, _)));
       -searching.
