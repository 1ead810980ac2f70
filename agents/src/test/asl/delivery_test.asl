// Skill test of delivery to the storage area (skills/delivery.asl): the set-up gives the middleware
// the storage point; a cylinder picked is carried there, the robot aligned by the compass; at the
// storage point it is put down and the robot turns around and leaves; the area is never entered
// without a cylinder; an obstacle on the way is gone round by a detour; no progress means an escape.
// The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/delivery.asl") }

maxSpeed(100).
travelSpeed(100).           // far sight's
storagePoint(0.4, -0.4).    // the world's, as the launcher gives them
storageRadius(0.1).
location(0, 0, 0).
orientation(90).

// every heading computed is 90 degrees; every other operation succeeds
mock_operation(computeAngle(_, _, _, _, 90), ok).
mock_operation(_, ok).

// what the skill needs of avoidance, recovery and sweep
+!avoid(D) <- +avoided(D); -avoiding.
+!escape <- +escaped.
+!found <- +foundCalled.
+!nextWaypoint <- +nextWaypointCalled.
// random motion (the last +!move plan)
+!move(N) <- +moved(N).

@[test]
+!test_set_up_gives_the_storage_point_and_the_area_without_cylinders
    <- !forget_calls; !setUpDelivery;
       !assert_true(mock_called(deltaBased(false)));
       !assert_true(mock_called(setUpTargetPoint(0.4, 0, -0.4)));
       !assert_true(mock_called(ignoreCylindersNear(0.4, -0.4, C)) & C > 0.189 & C < 0.191);  // radius + 9 cm
       !assert_true(mock_called(setThreshold(0.04)));
       !assert_true(targetPoint(0.4, -0.4)).

@[test]
+!test_a_picked_cylinder_is_carried_towards_the_storage_point
    <- !forget_calls; +picked(true); +picking;
       !go_ahead;
       !assert_true(delivering & ~delivered & not picking);
       !assert_true(foundCalled);                                       // the search has done its job
       !assert_true(mock_called(computeAngle(0, 0, 0.4, -0.4, 90)));    // the heading from GPS
       !assert_true(desired(90));
       !assert_true(mock_called(setSpeeds(100, 100))).                  // aligned: on at travel speed

@[test]
+!test_balance_turns_towards_the_desired_heading
    <- !forget_calls; -+desired(90); -+orientation(100);
       !!balance;
       !until(mock_called(setSpeeds(-10, 25)), 2000);
       !assert_true(mock_called(setSpeeds(-10, 25)));
       !assert_false(mock_called(setSpeeds(25, -10)));
       -+orientation(90.3);                                             // within the window
       !until(mock_called(setSpeeds(100, 100)), 2000);
       !assert_true(mock_called(stop));
       !forget_calls; -+orientation(80); !!balance;
       !until(mock_called(setSpeeds(25, -10)), 2000);
       -+orientation(90);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       !assert_true(mock_called(setSpeeds(25, -10))).

// an agent that believes quickTurn(V, A) turns at V while more than A degrees off, the shorter way
// (across north too), then slowly
@[test]
+!test_a_quick_turn_until_the_last_degrees
    <- !forget_calls; +quickTurn(50, 15); -+desired(90); -+orientation(300);
       !!balance;
       !until(mock_called(setSpeeds(50, -50)), 2000);
       !assert_true(mock_called(setSpeeds(50, -50)));                   // right, across north
       !assert_false(mock_called(setSpeeds(-50, 50)) | mock_called(setSpeeds(25, -10)));
       -+orientation(80);                                               // 10 degrees off: slowly
       !until(mock_called(setSpeeds(25, -10)), 2000);
       !assert_true(mock_called(setSpeeds(25, -10)));
       -+orientation(90);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       !forget_calls; -+orientation(150); !!balance;
       !until(mock_called(setSpeeds(-50, 50)), 2000);
       -+orientation(90);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       -quickTurn(50, 15);
       !assert_true(mock_called(setSpeeds(-50, 50))).                   // left

// quickTurns: the skill's quickTurnAt(50, 15), as navigation and tidy-up believe it
@[test]
+!test_quick_turns_at_the_skills_speed
    <- !forget_calls; +quickTurns; -+desired(90); -+orientation(30);
       !!balance;
       !until(mock_called(setSpeeds(50, -50)), 2000);
       -+orientation(90);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       -quickTurns;
       !assert_true(mock_called(setSpeeds(50, -50)));
       !assert_false(mock_called(setSpeeds(25, -10))).

@[test]
+!test_balanced_across_north
    <- !forget_calls; -+desired(0.3); -+orientation(359.9);
       !balance;
       !assert_false(mock_called(setSpeeds(25, -10)) | mock_called(setSpeeds(-10, 25)));
       !assert_true(mock_called(setSpeeds(100, 100))).

@[test]
+!test_at_the_storage_point_the_cylinder_is_put_down_and_the_robot_leaves
    <- !forget_calls; -+orientation(90); -picked(true);
       !!perceive(targetReached);
       !until(mock_called(putDown) & desired(270), 2000);
       !assert_true(mock_called(stopAcquireDistance));
       !assert_false(delivering);
       !assert_true(stored(1));
       !assert_true(desired(270));                                      // the opposite heading
       -+orientation(270);                                              // turned around
       !until(mock_called(waitExit), 2000);
       !assert_true(mock_called(forward));
       !!perceive(outOfStorageArea);
       !until(not ~delivered, 2000);
       !assert_true(mock_called(restartAcquireDistance));
       !assert_false(~delivered);
       -targetReached; -outOfStorageArea.

@[test]
+!test_a_wider_threshold_after_a_delivery_up_to_max_ray
    <- !forget_calls; -+maxRay(0.1);
       !raiseRay;
       !assert_true(mock_called(setThreshold(0.07)));
       -+maxRay(0.04); -+threshold(0.07);
       !raiseRay;
       !assert_true(mock_called(setThreshold(0.04)));
       !assert_true(ray(0.04));
       -+threshold(0.04).

@[test]
+!test_the_storage_area_is_not_entered_without_a_cylinder
    <- !forget_calls; -nextWaypointCalled; -+orientation(90); +searching; -+location(0.3, 0, -0.3);
       !!perceive(noAccess);
       !until(nextWaypointCalled, 4000);
       -noAccess; -searching;
       !assert_true(gettingOut);
       !assert_true(mock_called(stop));
       !assert_true(mock_called(computeAngle(0.4, -0.4, 0.3, -0.3, _))); // away from the storage point
       !assert_true(mock_called(forward));
       !assert_true(nextWaypointCalled).                                // the search goes on

// an agent that believes waypointPastStorage (tidy-up) keeps a waypoint away from the storage point
// (here (0.4, -0.4), the robot at (0.3, -0.3)), and gives up one beyond it
@[test]
+!test_a_waypoint_away_from_the_storage_area_is_kept_at_its_edge
    <- !forget_calls; -nextWaypointCalled; -+orientation(90); +searching; -+location(0.3, 0, -0.3);
       +waypointPastStorage; +waypoint(-0.8, 0.5, 0);
       !!perceive(noAccess);
       !until(mock_called(forward), 4000); .wait(300);
       -noAccess;
       !assert_true(mock_called(forward));                              // out, away from the area
       !assert_false(nextWaypointCalled);                               // the waypoint kept
       -waypoint(_, _, _); +waypoint(0.8, -0.8, 0); !forget_calls;
       !!perceive(noAccess);
       !until(nextWaypointCalled, 4000);
       -noAccess; -searching; -waypointPastStorage; -waypoint(_, _, _);
       !assert_true(nextWaypointCalled).                                // the way led past the storage point

@[test]
+!test_with_a_cylinder_the_robot_enters_the_storage_area
    <- !forget_calls; +delivering; +firstTime;
       !!perceive(noAccess);
       !until(insideArea, 2000);
       !assert_true(insideArea);
       !assert_false(firstTime);
       !assert_true(mock_called(stopAcquireDistance));
       !assert_false(gettingOut & mock_called(stop));
       -noAccess; -insideArea; -delivering.

@[test]
+!test_an_obstacle_on_the_way_is_gone_round_and_the_robot_realigns
    <- !forget_calls; -avoided(_); +delivering; -+detours(0); -+orientation(90); +delta(30);
       !!perceive(obstacle(true));
       !until(mock_called(setSpeeds(100, 100)), 4000);
       -obstacle(true); -delivering;
       !assert_true(avoided(30));
       !assert_true(detours(1));
       !assert_true(mock_called(forward));                              // past the obstacle first
       !assert_true(mock_called(computeAngle(_, _, 0.4, -0.4, _))).     // then the heading again

@[test]
+!test_no_progress_on_the_way_means_an_escape_and_a_new_heading
    <- !forget_calls; -escaped; +delivering;
       !!perceive(stuck);
       !until(mock_called(setSpeeds(100, 100)), 4000);
       -stuck; -delivering;
       !assert_true(escaped);
       !assert_true(mock_called(computeAngle(_, _, 0.4, -0.4, _)));
       !assert_false(avoiding).

// carried into the area past the storage point (a wall following), the robot is halted there: no
// progress means turning to the storage point and going on
@[test]
+!test_no_progress_in_the_storage_area_with_the_cylinder_heads_for_the_storage_point
    <- !forget_calls; -escaped; +delivering; +insideArea;
       !!perceive(stuck);
       !until(mock_called(setSpeeds(100, 100)), 4000);
       -stuck; -insideArea; -delivering;
       !assert_true(mock_called(computeAngle(_, _, 0.4, -0.4, _)));
       !assert_true(mock_called(setSpeeds(100, 100)));
       !assert_false(escaped).

// in the area nothing steers: come in a few degrees off, the robot missed the point and slid along
// the wall beside it, never stuck; areaLimit after coming in without the put-down, it turns to the
// storage point again and goes on (and again after another areaLimit)
@[test]
+!test_no_put_down_soon_after_entering_the_area_heads_for_the_storage_point
    <- !forget_calls; -+areaLimit(300); -+orientation(90); +delivering; +firstTime;
       !!perceive(noAccess);
       !until(insideArea, 2000);
       .wait(100);
       !assert_false(mock_called(computeAngle(_, _, 0.4, -0.4, _)));   // not yet
       !until(mock_called(computeAngle(_, _, 0.4, -0.4, _)), 2000);
       !assert_true(mock_called(computeAngle(_, _, 0.4, -0.4, _)));
       !until(mock_called(setSpeeds(100, 100)), 2000);
       !assert_true(mock_called(setSpeeds(100, 100)));
       !forget_calls;
       !until(mock_called(computeAngle(_, _, 0.4, -0.4, _)), 2000);
       !assert_true(mock_called(computeAngle(_, _, 0.4, -0.4, _)));    // again
       -noAccess; -insideArea; -delivering; .wait(400); -+areaLimit(10000).

// put down in time, the watch does nothing
@[test]
+!test_a_put_down_in_time_ends_the_area_watch
    <- !forget_calls; -+areaLimit(300); -+orientation(90); +delivering; +firstTime;
       !!perceive(noAccess);
       !until(insideArea, 2000);
       -insideArea; -delivering;                                        // put down, out
       .wait(500);
       -noAccess; -+areaLimit(10000);
       !assert_false(mock_called(computeAngle(_, _, 0.4, -0.4, _))).

@[test]
+!test_random_motion_waits_while_delivering
    <- -moved(_); +delivering; +~delivered;
       !!move(0.1);
       .wait(200);
       !assert_false(moved(_));
       -delivering; -~delivered;
       !until(moved(_), 2000);
       !assert_true(moved(0.1)).
