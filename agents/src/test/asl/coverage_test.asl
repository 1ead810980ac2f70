// Skill test of avoidance and coverage for the two-sensor MyBot (skills/coverage.asl): its set-up
// gives the middleware dead reckoning and (in a large arena) closer obstacle levels; an obstacle
// makes the robot turn away from its side and veer off along an arc once it clears; obstacles that
// come too often lead to an escape; random motion takes straight legs, cut short over floor
// already crossed, and turns towards new floor. The operations are mocked (agents/README.md
// "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/coverage.asl") }

maxSpeed(100).
arena(3, 3).
mock_operation(_, ok).

// what the skill needs of recovery: the obstacle clears at once
+!clear <- -obstacle(true); +obstacle(false).

// a new obstacle percept (the previous one gone)
+!obstacle_ahead(D) <- -+delta(D); -obstacle(false); -obstacle(true); !!perceive(obstacle(true)).

@[test]
+!test_set_up_in_a_large_arena_gives_odometry_and_closer_obstacle_levels
    <- !forget_calls; !setUpCoverage;
       !assert_true(mock_called(odometry(0.001, 0.09)));
       !assert_true(mock_called(exploreHorizon(0.6)));
       !assert_true(mock_called(obstacleLevels(480, 300)));
       !assert_true(mock_called(deltaLimit(150))).

@[test]
+!test_set_up_in_a_small_arena_keeps_the_thesis_obstacle_levels
    <- !forget_calls; -+arena(1, 1); !setUpCoverage; -+arena(3, 3);
       !assert_true(mock_called(odometry(_, _)));
       !assert_false(mock_called(obstacleLevels(_, _))).

@[test]
+!test_set_up_in_a_narrow_arena_gives_closer_obstacle_levels
    <- !forget_calls; -+arena(0.8, 2.4); !setUpCoverage; -+arena(3, 3);
       !assert_true(mock_called(obstacleLevels(480, 300)));
       !assert_true(mock_called(deltaLimit(150))).

// from 1.5 m2 on (closeArea), not only 2: a room of a split arena of 1.5-2 m2 stayed unvisited
@[test]
+!test_set_up_from_one_and_a_half_square_metres_gives_closer_obstacle_levels
    <- !forget_calls; -+arena(1.2, 1.4); !setUpCoverage;
       !assert_true(mock_called(obstacleLevels(480, 300)));
       !forget_calls; -+arena(1.2, 1.2); !setUpCoverage; -+arena(3, 3);
       !assert_false(mock_called(obstacleLevels(_, _))).

@[test]
+!test_an_obstacle_on_the_left_turns_right_then_veers_away
    <- !forget_calls; -+obstacleTimes([]); !obstacle_ahead(40);
       !until(mock_called(setSpeeds(100, V)) & V < 100 & V > 0, 2000);
       !assert_true(mock_called(stop));
       !assert_true(mock_called(setSpeeds(100, -100)));                  // on the spot, away from it
       !assert_true(mock_called(setSpeeds(100, V)) & V < 100 & V > 0);   // the arc, still away
       !until(not veering, 2000);
       !assert_false(avoiding | veering);
       ?obstacleTimes(L);
       !assert_equals(1, .length(L)).                                     // noted for the trap count

// in a narrow arena, a box the left sensor read a moment ago and reads no more sits at the left
// flank: an obstacle on the right, whose usual turn and veer go left into that box, turns the robot
// back instead
@[test]
+!test_a_box_just_passed_on_the_side_turned_to_turns_the_robot_back_in_a_narrow_arena
    <- !forget_calls; -+obstacleTimes([]); -+arena(0.8, 2.4);
       -+leftSensor(600); !until(strongLeft(_), 500); -+leftSensor(0); -+rightSensor(250);
       !obstacle_ahead(-250);                                             // on the right: the usual turn is left
       !until(avoiding, 1000);
       !until(not avoiding, 3000);
       !assert_true(mock_called(setSpeeds(100, -100)));                   // the half turn on the spot
       !assert_false(mock_called(setSpeeds(-100, 100)));                  // not the turn left
       !assert_false(mock_called(setSpeeds(V, 100)) & V > 0 & V < 100);   // nor the veer left
       !assert_false(veering);
       -leftSensor(_); -rightSensor(_); -strongLeft(_); -+arena(3, 3).

// in an arena 1 m or more across, the same box leaves the usual turn left and its veer
@[test]
+!test_a_box_just_passed_on_the_side_turned_to_leaves_the_usual_turn_in_a_wider_arena
    <- !forget_calls; -+obstacleTimes([]); -+arena(1.5, 2.4);
       -+leftSensor(600); .wait(100); -+leftSensor(0); -+rightSensor(250);
       !obstacle_ahead(-250);
       !until(mock_called(setSpeeds(V, 100)) & V > 0 & V < 100, 2000);
       !assert_true(mock_called(setSpeeds(-100, 100)));
       !assert_false(mock_called(setSpeeds(100, -100)));
       !assert_false(strongLeft(_));                                      // not watched there
       !until(not veering, 2000);
       -leftSensor(_); -rightSensor(_); -+arena(3, 3).

// the same box still read (in the cone, not at the flank): the usual turn left
@[test]
+!test_a_box_still_read_on_the_side_turned_to_leaves_the_usual_turn
    <- !forget_calls; -+obstacleTimes([]); -+arena(0.8, 2.4);
       -+leftSensor(600); !until(strongLeft(_), 500); -+leftSensor(40); -+rightSensor(250);
       !obstacle_ahead(-250);
       !until(mock_called(setSpeeds(V, 100)) & V > 0 & V < 100, 2000);
       !assert_true(mock_called(setSpeeds(-100, 100)));
       !assert_false(mock_called(setSpeeds(100, -100)));
       !until(not veering, 2000);
       -leftSensor(_); -rightSensor(_); -strongLeft(_); -+arena(3, 3).

@[test]
+!test_a_central_obstacle_makes_the_robot_back_off_and_turn_around
    <- !forget_calls; -+obstacleTimes([]); !obstacle_ahead(0);
       !until(not avoiding & mock_called(turnAround), 2000);
       !assert_true(mock_called(backward));
       !assert_true(mock_called(turnAround)).

// a veer under way (begun in the motion goal, which the new obstacle ends with it) must not stay
// believed when the new avoidance does not veer: random motion would wait for ever
@[test]
+!test_a_new_obstacle_ends_a_veer_under_way
    <- !forget_calls; -+obstacleTimes([]); +veering;
       !obstacle_ahead(0);                                                // front: no veer of its own
       !until(not avoiding & mock_called(turnAround), 2000);
       !assert_false(veering).

// corridor steering ended by an obstacle avoids it and veers; a new obstacle during that veer starts
// an avoidance of its own (here a trap's escape, which takes a while), whose "avoiding" the
// steering's intention must not take away when its veer ends: random motion would then avoid too
@[test]
+!test_a_steering_ended_in_a_veer_leaves_a_new_avoidance_believed
    <- !forget_calls; -+obstacleTimes([]); -+leftSensor(100); -+rightSensor(60); -+walledIn(true);
       !obstacle_ahead(40);                                               // both walls seen: steering
       !until(mock_called(setSpeeds(100, V)) & V < 100 & V > 50, 1000);
       -+walledIn(false);                                                 // out of the corridor, the obstacle there
       !until(veering, 1000);                                             // avoided, and the veer under way
       .system_time(T); -+obstacleTimes([T, T, T, T]);
       !obstacle_ahead(40);                                               // a trap: the escape
       !until(.intend(escape), 1000);
       .wait(400);                                                        // the first veer (300 ms) over
       !assert_true(.intend(escape));
       !assert_true(avoiding);
       !until(not avoiding, 4000);
       -+obstacleTimes([]); -leftSensor(_); -rightSensor(_).

@[test]
+!test_obstacles_too_often_lead_to_an_escape
    <- !forget_calls; .system_time(T);
       -+obstacleTimes([T, T, T, T]);                                     // the fifth makes a trap
       !obstacle_ahead(40);
       !until(obstacleTimes([]) & not avoiding, 5000);
       !assert_true(mock_called(setSpeeds(-100, -100)));                  // a step back
       !assert_true(mock_called(setSpeeds(100, -100)));                   // the turn on the spot
       !assert_true(obstacleTimes([]));                                   // the count starts again
       !assert_false(veering).

@[test]
+!test_old_obstacles_do_not_count_for_a_trap
    <- .system_time(T); -+obstacleTimes([T - 20000, T - 30000]);
       !noteObstacle;
       ?obstacleTimes(L);
       !assert_equals(1, .length(L)).

@[test]
+!test_a_straight_leg_is_cut_short_over_floor_crossed_before
    <- !forget_calls; -stale; -obstacle(true); +mock_operation(staleTime(5000), ok);
       !!move(0.2);
       !until(stale, 2000);
       -mock_operation(staleTime(5000), ok);
       !assert_true(mock_called(setSpeeds(100, 100)));
       !assert_true(stale).

@[test]
+!test_a_turn_goes_towards_new_floor
    <- !forget_calls; -stale; -+obstacleTimes([]);
       +mock_operation(exploreTurn(100, "left", 50), ok); +mock_operation(staleTime(0), ok);
       !!move(0.8);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       .drop_desire(move(_));
       !assert_true(mock_called(exploreTurn(100, "left", 50)));
       !assert_true(mock_called(setSpeeds(-100, 100))).

@[test]
+!test_no_turn_just_after_an_obstacle
    <- !forget_calls; .system_time(T); -+obstacleTimes([T]);
       !!move(0.8);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       .drop_desire(move(_));
       !assert_false(mock_called(exploreTurn(_, _, _))).

@[test]
+!test_random_motion_waits_while_avoiding
    <- !forget_calls; -+obstacleTimes([]); +avoiding; -obstacle(true);
       !!move(0.2);
       .wait(200);
       !assert_false(mock_called(setSpeeds(_, _)));
       -avoiding;
       !until(mock_called(setSpeeds(100, 100)), 2000);
       .drop_desire(move(_));
       !assert_true(mock_called(setSpeeds(100, 100))).

@[test]
+!test_a_covered_room_in_a_larger_arena_sends_the_robot_to_the_nearest_frontier
    <- !forget_calls; -+obstacleTimes([]); -seeking(_); -soughtAt(_); -stale; -+seekWindow(1); // the test's clock is young
       +seekShare(0.3);                                                               // the agent turns seeking on
       +mock_operation(freshCells(1, 2), ok); +mock_operation(visitedArea(1.2), ok);  // 1.2 of 9 m2
       +mock_operation(frontierTurn(100, "right", 50, 0.1), ok);                      // a waypoint 10 cm away
       !!move(0.8);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       !assert_true(seeking(_));
       .drop_desire(move(_));
       -mock_operation(freshCells(1, 2), ok); -mock_operation(visitedArea(1.2), ok);
       -mock_operation(frontierTurn(100, "right", 50, 0.1), ok);
       -+seekWindow(30000); -seeking(_); -seekShare(_);
       !assert_true(mock_called(setSpeeds(100, -100)));                                // the turn towards it
       !assert_false(mock_called(exploreTurn(_, _, _))).

@[test]
+!test_seeking_ends_when_there_is_no_frontier
    <- !forget_calls; -+obstacleTimes([]); -soughtAt(_); .system_time(T); +seeking(T + 10000);
       +mock_operation(frontierTurn(100, "none", 0, 0), ok);
       !!move(0.2);
       !until(not seeking(_), 2000);
       .drop_desire(move(_));
       -mock_operation(frontierTurn(100, "none", 0, 0), ok);
       !assert_false(seeking(_));
       !assert_true(soughtAt(_));
       -soughtAt(_).

@[test]
+!test_no_seeking_while_new_floor_still_comes_or_most_of_the_arena_is_crossed
    <- !forget_calls; -+obstacleTimes([]); -seeking(_); -soughtAt(_); -stale; -+seekWindow(1); // the test's clock is young
       +seekShare(0.3);                                                               // the agent turns seeking on
       +mock_operation(freshCells(1, 20), ok); +mock_operation(visitedArea(1.2), ok);
       +mock_operation(exploreTurn(100, "left", 50), ok); +mock_operation(staleTime(0), ok);
       !!move(0.8);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       .drop_desire(move(_));
       -mock_operation(freshCells(1, 20), ok); -soughtAt(_);
       !assert_false(seeking(_));
       !forget_calls; +mock_operation(freshCells(1, 2), ok); +mock_operation(visitedArea(5), ok); // 5 of 9 m2
       !!move(0.8);
       !until(mock_called(freshCells(_, _)), 2000);
       .wait(100);
       .drop_desire(move(_));
       -mock_operation(freshCells(1, 2), ok); -mock_operation(visitedArea(5), ok); -soughtAt(_);
       -+seekWindow(30000); -seekShare(_);
       !assert_false(seeking(_)).

@[test]
+!test_no_seeking_in_an_agent_that_does_not_turn_it_on
    <- !forget_calls; -+obstacleTimes([]); -seeking(_); -soughtAt(_); -stale; -+seekWindow(1);
       +mock_operation(freshCells(1, 2), ok); +mock_operation(visitedArea(1.2), ok);
       +mock_operation(exploreTurn(100, "left", 50), ok); +mock_operation(staleTime(0), ok);
       !!move(0.8);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       .drop_desire(move(_));
       -mock_operation(freshCells(1, 2), ok); -mock_operation(visitedArea(1.2), ok);
       -+seekWindow(30000);
       !assert_false(mock_called(freshCells(_, _)));
       !assert_false(seeking(_)).

// corridor steering's cut-off stays under the level that signals an obstacle: the closer levels'
// 480 leave it at 400; a small arena keeps the thesis' 350, and with it the cut-off
@[test]
+!test_the_corridor_cut_off_stays_under_the_obstacle_level
    <- !assert_true(steerCut(400));
       -arena(3, 3); +arena(1.2, 1.2);
       !assert_true(steerCut(350));
       -arena(1.2, 1.2); +arena(3, 3).
