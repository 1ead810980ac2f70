// Skill test of the sweep by look points (skills/look-points.asl): the sweep's waypoints are the
// centres of a grid lookSpacing apart, none in the storage area, the nearest first; a point reached
// within lookReach gives the next and a look around; with none left a new round begins; a place
// looked for again too long gives way to the look points; an avoidance cut off is cleared on no
// progress. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/look-points.asl") }
{ include("../../main/asl/skills/sweep.asl") }

lookSpacing(1).              // navigation's
arena(3, 2).                 // the world's, as the launcher gives them
storagePoint(1, 0.5).
storageClearance(0.15).      // delivery's
location(0.9, 0, -0.4).

mock_operation(computeAngle(_, _, _, _, 45), ok).
mock_operation(_, ok).

// what the skill needs of sweep (its look around is 6.8 s: no maxSpeed here, this one instead) and recovery
+!lookAround <- +looked.
+!escape <- +escaped.
// heading's, for the step towards a point kept
+!balance.
+!aimAt(X, Z) <- -+aim(X, Z).

@[test]
+!test_the_look_points_are_a_grid_off_the_storage_area_the_nearest_first
    <- -sweep(_); -+location(0.9, 0, -0.4);
       !planSweep;
       !assert_true(waypoint(1, -0.5, _));                              // (1, 0.5): the storage area
       !assert_true(sweep([[-1, -0.5], [-1, 0.5], [0, -0.5], [0, 0.5]])).

@[test]
+!test_a_point_reached_gives_the_nearest_left_and_a_look_around
    <- -looked; -+sweep([[-1, -0.5], [0, 0.5], [0, -0.5]]); -+waypoint(1, -0.5, 0); -+location(1, 0, -0.4);
       !sweepStep;                                                      // 0.1 m from it: reached
       !assert_true(looked);
       !assert_true(waypoint(0, -0.5, _));
       !assert_true(sweep([[-1, -0.5], [0, 0.5]])).

@[test]
+!test_with_no_point_left_a_new_round_begins
    <- -+sweep([]); -+location(-0.9, 0, 0.4);
       !nextWaypoint;
       !assert_true(waypoint(-1, 0.5, _));
       .count(sweep(L) & .length(L, 4), N); !assert_true(N == 1).

@[test]
+!test_a_place_looked_for_again_too_long_gives_way_to_the_look_points
    <- -+sweep([[0, 0.5]]); -+location(0, 0, 0.3); -+waypoint(-0.6, 0.2, 0);
       +lookingAgain(-0.6, 0.2, 0);
       !until(lookAgainFrom(-0.6, 0.2, _), 500);
       ?lookAgainFrom(-0.6, 0.2, T); -lookAgainFrom(-0.6, 0.2, T); +lookAgainFrom(-0.6, 0.2, T - 41000);
       !sweepStep;
       !assert_false(lookingAgain(_, _, _));
       !assert_true(waypoint(0, 0.5, _)).

// an avoidance cut off (its move ended by a cylinder's reach) left "avoiding" behind: no progress
// then is an escape and the next waypoint, and "avoiding" goes (without it the robot stood still)
@[test]
+!test_no_progress_with_avoiding_left_behind_means_an_escape
    <- -escaped; -picking; -travelling; -insideArea; +avoiding; -+sweep([[0, 0.5]]); -+location(0, 0, 0.3);
       !!perceive(stuck);
       !until(not avoiding, 3000);
       -stuck;
       !assert_false(avoiding);
       !assert_true(escaped);
       !assert_true(waypoint(0, 0.5, _)).

// a look point whose patience ran out while the robot still came nearer it is kept (its clock set
// to run out lookNearing after the last approach); one the robot came no nearer is skipped, and so
// is one kept lookPointMost in all
@[test]
+!test_a_look_point_still_neared_is_kept_past_its_patience
    <- -+sweep([[0, 0.5]]); -+location(-0.9, 0, -0.2); +waypointPatience(60000); +lookNearing(10000);
       .system_time(T); -+waypoint(-1, -0.5, T - 61000); -+lookPointSet(-1, -0.5, T - 61000);
       -+closest(0.3); -+closerAt(T - 4000);
       !sweepStep;                                                      // neared 4 s ago: kept
       !assert_true(waypoint(-1, -0.5, T2) & T2 > T - 55000);
       -+closerAt(T - 11000); -+waypoint(-1, -0.5, T - 61000);
       !sweepStep;                                                      // not for 11 s: skipped
       !assert_true(waypoint(0, 0.5, _));
       -+sweep([[0, 0.5]]); -+closerAt(T - 2000); -+waypoint(-1, -0.5, T - 61000); -+lookPointSet(-1, -0.5, T - 121000);
       !sweepStep;                                                      // 121 s in all: skipped
       !assert_true(waypoint(0, 0.5, _));
       -waypointPatience(60000); -lookNearing(10000).

// a search whose round is gone (a goal ended @newLookRound between forgetting the round's end and planning
// the next) plans a new round, the nearest point first: sweep's @noWaypoint did nothing, at every step
@[test]
+!test_a_search_whose_round_is_gone_plans_a_new_one
    <- -sweep(_); -waypoint(_, _, _); -+location(-0.9, 0, -0.4); +searching;
       !nextWaypoint;
       !assert_true(waypoint(-1, -0.5, _));
       -searching; -sweep(_); -waypoint(_, _, _).
