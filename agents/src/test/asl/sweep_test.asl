// Skill test of the sweep search (skills/sweep.asl): the sweep's waypoints are lanes across the
// arena, never in the storage area; each step aligns towards the waypoint and goes on, a waypoint
// reached or not come closer to in time gives way to the next, with a look around now and then; a
// cylinder found ends the sweep; a while without one starts it. The operations are mocked
// (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/sweep.asl") }

maxSpeed(100).
arena(2, 2).                 // the world's, as the launcher gives them
storagePoint(0.75, 0.75).
storageClearance(0.15).      // delivery's
location(0, 0, 0).

// every heading computed is 45 degrees; every other operation succeeds
mock_operation(computeAngle(_, _, _, _, 45), ok).
mock_operation(_, ok).

// what the skill needs of delivery and recovery
+!balance <- +balanced.
+!aimAt(X, Z) <- -+aim(X, Z).   // heading's: the straight way
+!escape <- +escaped.

// the look around of a waypoint reached is long (6.8 s): a test stops it once it has started
+!recently_looked <- .system_time(T); -+lastLook(T).

@[test]
+!test_the_sweep_runs_along_lanes_and_leaves_out_the_storage_area
    <- !planSweep;
       !assert_true(waypoint(-0.75, -0.75, _));                         // the first lane's start
       !assert_true(sweep([[0.75, -0.75], [0.75, -0.25], [-0.75, -0.25], [-0.75, 0.25], [0.75, 0.25],
                           [-0.75, 0.75], [-0.75, -0.75]]));            // back and forth; the first at the end
       !assert_true(closest(1000)).

// an agent's own sweepFrom(Fx, Fz) (search-memory: the corner nearest the robot) moves the lanes'
// start to the corner -Fx * W / 2, -Fz * D / 2, the lanes in the same order from there
@[test]
+!test_an_agents_sweep_from_begins_the_lanes_at_its_corner
    <- -sweep(_); +sweepFrom(-1, -1);
       !planSweep;
       -sweepFrom(-1, -1);
       !assert_true(waypoint(-0.75, 0.75, _));                          // (0.75, 0.75): the storage area
       !assert_true(sweep([[-0.75, 0.25], [0.75, 0.25], [0.75, -0.25], [-0.75, -0.25], [-0.75, -0.75],
                           [0.75, -0.75], [-0.75, 0.75]])).

// a world without a storage area (object picking): no waypoint is left out
@[test]
+!test_without_a_storage_point_every_waypoint_is_kept
    <- -sweep(_); -storagePoint(0.75, 0.75);
       !planSweep;
       +storagePoint(0.75, 0.75);
       !assert_true(sweep([[0.75, -0.75], [0.75, -0.25], [-0.75, -0.25], [-0.75, 0.25], [0.75, 0.25],
                           [0.75, 0.75], [-0.75, 0.75], [-0.75, -0.75]])).

// an arena under two spacings deep (0.96 m: one lane at z = -0.23) whose lane's other end lies by
// the storage area would leave one waypoint: it gets two lanes, at -0.23 and 0.23
@[test]
+!test_a_shallow_arena_with_one_waypoint_left_gets_two_lanes
    <- -sweep(_); -+arena(0.96, 0.96); -+storagePoint(0.384, -0.384);
       !planSweep;
       -+arena(2, 2); -+storagePoint(0.75, 0.75);
       ?waypoint(X0, Z0, _);
       !assert_equals(-0.23, X0, 0.001); !assert_equals(-0.23, Z0, 0.001);
       ?sweep([[X1, Z1], [X2, Z2], [X3, Z3]]);                           // three, the first at the end
       !assert_equals(0.23, X1, 0.001); !assert_equals(0.23, Z1, 0.001);
       !assert_equals(-0.23, X2, 0.001); !assert_equals(0.23, Z2, 0.001);
       !assert_equals(-0.23, X3, 0.001); !assert_equals(-0.23, Z3, 0.001).

@[test]
+!test_a_step_aligns_towards_the_waypoint_and_goes_on
    <- !forget_calls; -balanced; !recently_looked;
       .system_time(T); -+waypoint(0.75, -0.75, T - 1000); -+closest(1000);
       !sweepStep;
       !assert_true(mock_called(computeAngle(0, 0, 0.75, -0.75, 45)));
       !assert_true(desired(45) & balanced);
       !assert_true(mock_called(setSpeeds(100, 100)));
       ?closest(D);
       !assert_equals(D, 1.0607, 0.001);                                // closer than before: noted
       !assert_true(waypoint(0.75, -0.75, T2) & T2 >= T).               // and the patience starts again

@[test]
+!test_a_waypoint_reached_gives_way_to_the_next_and_a_look_around
    <- !forget_calls; -+sweep([[0.75, -0.25], [-0.75, -0.25]]);
       .system_time(T); -+waypoint(0.05, 0.05, T); -+location(0, 0, 0);
       !!sweepStep;
       !until(mock_called(setSpeeds(-50, 50)), 2000);
       .drop_desire(sweepStep);
       !assert_true(mock_called(setSpeeds(-50, 50)));                   // a full turn on the spot
       !assert_true(waypoint(0.75, -0.25, _)).

@[test]
+!test_a_waypoint_not_come_closer_to_in_time_is_skipped
    <- !forget_calls; !recently_looked; -+sweep([[-0.75, -0.25], [0.75, -0.25]]);
       .system_time(T); -+waypoint(0.75, -0.75, T - 30000);            // patience: 20 s
       !sweepStep;
       !assert_true(waypoint(-0.75, -0.25, _));
       !assert_false(mock_called(setSpeeds(_, _))).

@[test]
+!test_an_agents_own_patience_replaces_the_default
    <- ?patience(P1); +waypointPatience(60000); ?patience(P2); -waypointPatience(60000);
       !assert_equals(20000, P1);
       !assert_equals(60000, P2).

@[test]
+!test_a_look_around_every_while
    <- !forget_calls; .system_time(T); -+lastLook(T - 30000); -+waypoint(0.75, -0.75, T);
       !!sweepStep;
       !until(mock_called(setSpeeds(-50, 50)), 2000);
       .drop_desire(sweepStep);
       !assert_true(mock_called(setSpeeds(-50, 50)));
       !assert_true(lastLook(T2) & T2 >= T).

@[test]
+!test_random_motion_gives_way_to_the_sweep_while_searching
    <- !forget_calls; !recently_looked; +searching;
       .system_time(T); -+waypoint(0.75, -0.75, T);
       !move(0.3);
       !assert_true(mock_called(computeAngle(_, _, 0.75, -0.75, _))).

@[test]
+!test_a_cylinder_found_ends_the_sweep
    <- -+lastFound(0); +searching; .system_time(T0);
       !found;
       !assert_false(searching);
       !assert_false(waypoint(_, _, _));
       !assert_true(lastFound(T) & T >= T0).

@[test]
+!test_no_progress_means_an_escape_and_the_next_waypoint
    <- !forget_calls; -escaped; -+sweep([[-0.75, 0.25], [0.75, 0.25]]);
       !!perceive(stuck);
       !until(escaped & not avoiding, 2000);
       -stuck;
       !assert_true(escaped);
       !assert_true(waypoint(-0.75, 0.25, _));
       !assert_false(avoiding).

// the last test: the clock it starts goes on
@[test]
+!test_a_while_without_a_cylinder_starts_the_sweep
    <- -searching; -+searchAfter(100);
       !setUpSweep;                                                     // the clock looks every 5 s
       !assert_false(searching);
       !until(searching, 7000);
       !assert_true(searching);
       !assert_true(waypoint(_, _, _)).
