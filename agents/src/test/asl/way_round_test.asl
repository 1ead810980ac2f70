// Skill test of the way round a wall (skills/way-round.asl): an obstacle met again near an earlier
// one on the way to a target starts a boundary following on the side with the longer run along
// the wall, kept for the trip; the wall is kept at the side by the front sensors; the following
// ends when the target lies on the free side, or when the trip ends. The operations are mocked
// (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/way-round.asl") }

maxSpeed(100).
arena(2, 2).
location(0.5, 0, 0).
orientation(45).
targetPoint(0.9, 0.4).
leftSensor(0).
rightSensor(0).
travelling :- delivering.

// every heading computed is 45 degrees (towards +x and +z); every other operation succeeds
mock_operation(computeAngle(_, _, _, _, 45), ok).
mock_operation(_, ok).

// what the skill needs of heading
+!computeGap <- +gapComputed.
+!balance <- +balanced.
+!detour(D) <- +detoured(D).

@[test]
+!test_the_free_run_is_measured_to_the_arena_boundary
    <- ?freeRun(0, E); !assert_equals(E, 0.5, 0.001);           // from x = 0.5 to the wall at x = 1
       ?freeRun(180, W); !assert_equals(W, 1.5, 0.001);
       ?freeRun(-45, L); !assert_equals(L, 0.7071, 0.001);      // the nearer of the two walls met
       ?freeRun(135, R); !assert_equals(R, 1.4142, 0.001).

@[test]
+!test_an_obstacle_met_again_near_an_earlier_one_starts_the_following
    <- !forget_calls; +delivering; -+detours(0); -+detours(1);   // heading counts a detour here
       !assert_true(hitPoint(0.5, 0));
       +obstacle(true);
       !until(followingWall(_, _, _), 1000);
       // at 45 degrees the run along the wall is longer turning right (135) than left (-45):
       // the robot turns right, the wall on its left
       !assert_true(followingWall(left, _, _) & avoiding);
       !assert_true(mock_called(stop));
       -delivering; -obstacle(true);
       !until(not followingWall(_, _, _), 1000);
       !assert_false(followingWall(_, _, _) | avoiding).         // the trip ended: so did the following

// a fall (delivery's @fallCylinder) drops every desire and abolishes each forgetOnFall(B): a
// following it cut short goes with them, else later obstacles were taken for its wall
@[test]
+!test_a_fall_forgets_a_following_cut_short
    <- +followingWall(left, 0, 1); +followTarget(0.9, 0.4);
       for (forgetOnFall(B)) { .abolish(B) };
       !assert_false(followingWall(_, _, _) | followTarget(_, _)).

@[test]
+!test_an_obstacle_far_from_the_earlier_ones_is_left_to_heading
    <- +delivering; -+detours(0);
       +hitPoint(-0.5, -0.5);
       +obstacle(true);
       .wait(100);
       !assert_false(followingWall(_, _, _));
       -delivering; -obstacle(true).

// an agent that believes rehitsToFollow(2) detours round an obstacle met once near here before,
// and follows at the third
@[test]
+!test_an_agent_may_ask_for_more_obstacles_met_near_here_before_following
    <- +rehitsToFollow(2); +delivering; -+detours(0); -+detours(1);
       +obstacle(true);
       .wait(100);
       !assert_false(followingWall(_, _, _));                    // one met before: a detour
       -obstacle(true); -+location(0.55, 0, 0.05); -+detours(2);   // the next, 7 cm on
       +obstacle(true);
       !until(followingWall(_, _, _), 1000);
       !assert_true(followingWall(_, _, _));                     // two: a wall
       -delivering; -obstacle(true); -rehitsToFollow(2); -+location(0.5, 0, 0);
       !until(not followingWall(_, _, _), 1000).

@[test]
+!test_a_side_given_up_on_this_trip_is_not_chosen_again
    <- -+detours(0); +delivering;
       !chooseSide(S1); !assert_true(S1 == left);                 // the longer free run
       +gaveUpSide(left);
       !chooseSide(S2); !assert_true(S2 == right);
       +gaveUpSide(right);
       !chooseSide(S3); !assert_true(S3 == left);                 // both given up: the longer again
       -delivering; -+detours(0);                                // a new trip forgets them
       !assert_false(gaveUpSide(_) | hitPoint(_, _)).

@[test]
+!test_a_wall_that_leads_to_the_arena_boundary_is_followed_the_other_way
    <- .system_time(T); +delivering; -+location(0.95, 0, 0); -+detours(0);
       +followingWall(right, T - 5000, 1);
       !!followOrLeave(right, T - 5000, 1, 170);                  // at the boundary, target behind
       !until(gaveUpSide(right), 1000);
       !assert_true(gaveUpSide(right) & followingWall(left, _, _));
       -delivering; -+location(0.5, 0, 0);
       !until(not followingWall(_, _, _), 1000).

@[test]
+!test_the_target_on_the_free_side_ends_the_following
    <- !assert_true(canLeave(right, 1, -90));                    // wall on the right, target to the left
       !assert_false(canLeave(right, 1, 90));                    // target behind the wall
       !assert_false(canLeave(right, 1, -10));                   // about ahead: maybe a corridor's wall
       !assert_false(canLeave(right, 1, -175));                  // behind: its bearing flips sign
       !assert_true(canLeave(left, 1, 90));
       -+leftSensor(300);
       !assert_false(canLeave(right, 1, -90));                   // something ahead on the free side
       -+leftSensor(0).

@[test]
+!test_the_front_sensors_keep_the_wall_at_the_side
    <- !forget_calls; -+leftSensor(0); -+rightSensor(0);
       !alongWall(right);
       !assert_true(mock_called(setSpeeds(70, 21)));             // wall lost: arc towards it (right)
       !forget_calls; -+rightSensor(150);
       !alongWall(right);
       !assert_true(mock_called(setSpeeds(70, 59.5)));           // alongside: on, a little towards it
       !forget_calls; -+rightSensor(400);
       !alongWall(right);
       !assert_true(mock_called(setSpeeds(35, 70)));             // too close: away from it
       !forget_calls; -+leftSensor(300);
       !alongWall(right);
       !assert_true(mock_called(setSpeeds(-25, 25)));            // something ahead: turn away on the spot
       !forget_calls; -+leftSensor(0); -+rightSensor(0);
       !alongWall(left);
       !assert_true(mock_called(setSpeeds(21, 70))).             // mirrored for the wall on the left

@[test]
+!test_an_obstacle_met_when_the_sweep_comes_no_nearer_its_waypoint_starts_a_following_towards_it
    <- .system_time(T); +searching; -+waypoint(-0.9, 0, T - 30000); -+closerAt(T - 30000);
       -obstacle(true); +obstacle(true);
       !until(followingWall(_, _, _), 1000);
       !assert_true(followingWall(_, _, _) & followTarget(-0.9, 0) & followedTowards(-0.9, 0, 1, _));
       -obstacle(true); -searching;                               // a cylinder found: the search ends
       !until(not followingWall(_, _, _), 1000);
       !assert_false(followingWall(_, _, _) | followTarget(_, _) | avoiding).

@[test]
+!test_an_obstacle_met_while_the_sweep_comes_nearer_its_waypoint_is_left_to_avoidance
    <- .system_time(T); +searching; -+waypoint(-0.9, 0, T); -+closerAt(T);
       -obstacle(true); +obstacle(true);
       .wait(100);
       !assert_false(followingWall(_, _, _));
       -obstacle(true); -searching.

@[test]
+!test_the_second_following_towards_one_waypoint_takes_the_other_side
    <- .system_time(T); +searching; -+waypoint(-0.9, 0, T - 30000); -+closerAt(T - 30000);
       .abolish(followedTowards(_, _, _, _)); +followedTowards(-0.9, 0, 1, left);
       -obstacle(true); +obstacle(true);
       !until(followingWall(_, _, _), 1000);
       !assert_true(followingWall(right, _, _) & followedTowards(-0.9, 0, 2, right));
       -obstacle(true); -searching;
       !until(not followingWall(_, _, _), 1000);
       -+closerAt(T - 30000); +searching; +obstacle(true);        // two followings: no third
       .wait(100);
       !assert_false(followingWall(_, _, _));
       -obstacle(true); -searching.

@[test]
+!test_wedged_twice_along_a_wall_gives_the_following_up
    <- .system_time(T); +delivering; -+detours(0); +avoiding; +followingWall(right, T, 1); -wedgedAlong;
       +stuck;                                                    // the first time: back off, go on
       !until(wedgedAlong, 3000);
       -stuck; .wait(100);
       !assert_true(followingWall(right, _, _) & wedgedAlong);
       +stuck;                                                    // the second: not a wall, boxes
       !until(not followingWall(_, _, _), 3000);
       !assert_true(gaveUpSide(right));
       !assert_false(followingWall(_, _, _) | avoiding);
       -stuck; -delivering.

// a box straight ahead between the two front beams: the central sensor alone sees it
@[test]
+!test_a_box_seen_by_the_central_sensor_alone_is_turned_from_on_the_spot
    <- !forget_calls; -+leftSensor(0); -+rightSensor(150); +centralSensor(800);
       !alongWall(right);
       !assert_true(mock_called(setSpeeds(-25, 25)));
       !forget_calls; -+centralSensor(100);
       !alongWall(right);
       !assert_true(mock_called(setSpeeds(70, 59.5)));           // nothing ahead: alongside as before
       -centralSensor(_); -+rightSensor(0).

// the obstacle still seen when the following ends raises no new event: the trip goes round it
@[test]
+!test_a_trip_turned_to_its_target_with_the_wall_still_ahead_goes_round_it
    <- +delivering; +delta(300); +obstacle(true);
       !headAgain(left);
       !assert_true(gapComputed & balanced & detoured(300));
       -obstacle(true); -detoured(_);
       !headAgain(left);
       !assert_false(detoured(_));                                 // the way clear: no detour
       -delivering; -delta(_); -gapComputed; -balanced.


// an agent that believes turnToWall: a following just begun with the wall seen by the other front
// sensor alone turns on the spot (away from the side chosen) instead of arcing towards nothing;
// later in the following, or without the belief, the wall lost is the arc as before
@[test]
+!test_a_following_begun_with_the_wall_on_the_other_side_turns_to_it_first
    <- .system_time(T); +followingWall(right, T, 1); +turnToWall; !forget_calls;
       !steerAlong(0, 110, 1);                                   // the wall ahead-left only
       !assert_true(mock_called(setSpeeds(-25, 25)));
       !forget_calls; -followingWall(right, T, 1); +followingWall(right, T - 3000, 1);
       !steerAlong(0, 110, 1);                                   // 3 s on: the wall lost
       !assert_true(mock_called(setSpeeds(70, 21)));
       !forget_calls; -turnToWall; -followingWall(right, T - 3000, 1); +followingWall(right, T, 1);
       !steerAlong(0, 110, 1);                                   // without the belief: the arc
       !assert_true(mock_called(setSpeeds(70, 21)));
       -followingWall(right, T, 1).
