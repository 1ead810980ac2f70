// Skill tests of the experiment-4 robot (suspend-resume.asl): a low battery suspends the task,
// sends the robot to the charger, and resumes once it is charged and back. No robot, world or
// middleware: the artifact operations are mocked (mock_operation beliefs, see agents/README.md
// "Testing skills"), the percepts are added as beliefs. Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/suspend-resume.asl") }

// the world's landmarks, as the launcher gives them
arena(1.0, 1.0).
storagePoint(0.41, -0.41).
charger(-0.38, 0.38).

// the middleware exists (the initial phase finds it) but never connects; the heading computed
// towards any target is 90 degrees; every other operation succeeds
mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(computeAngle(_, _, _, _, 90), ok).
// the way along the route map: 2 m from the charger, 1 m from anywhere else
mock_operation(routeLength(-0.38, 0.38, _, _, 2.0), ok).
mock_operation(routeLength(_, _, _, _, 1.0), ok).
mock_operation(_, ok).

@[test]
+!test_low_battery_suspends_the_move_and_heads_for_the_charger
    <- +location(0.1, 0, 0.2); +orientation(90); +battery(470);
       !!perceive(lowBattery);
       ?charger(Cx, Cz);
       !until(mock_called(setUpTargetPoint(Cx, 0, Cz)), 10000);
       !assert_true(charging);
       !assert_true(mock_called(mark(0.1, 0, 0.2)));                 // the point to come back to
       !assert_true(mock_called(setUpTargetPoint(Cx, 0, Cz)));       // the charger is the target
       !!move(0.5);                                                  // a random move, while charging
       .wait(200);
       !assert_true(.intend(move(_))).                               // waits for the end of the recharge

@[test]
+!test_charged_robot_returns_to_the_marked_point_and_resumes
    <- !until(.intend(reachCharger), 10000);
       !!perceive(targetReached);                                    // at the charger
       !until(.intend(waitCharged), 10000);
       !assert_true(mock_called(stopAcquireDistance));
       -+battery(950); !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       !assert_true(mock_called(setUpTargetPoint(0.1, 0, 0.2)));     // back to where the battery went low
       -targetReached; !!perceive(targetReached);
       !until(not charging, 10000);
       !assert_false(charging).

// the way back's time runs out: tried again while the robot came markedProgress nearer the marked
// point on the try (a give-up leaves the episode open), given up once a try brought it no nearer
@[test]
+!test_a_way_back_still_coming_nearer_is_tried_again_when_its_time_runs_out
    <- !until(not charging, 10000); !forget_calls; -+tripTimeout(600);
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.1); -+battery(470);
       !!perceive(lowBattery);
       !until(.intend(reachCharger), 10000);
       -+location(-0.38, 0, 0.38); !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); -targetReached; !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       -+location(0.2, 0, 0);                                        // 0.83 m -> 0.14 m from the mark
       !until(markedFrom(D) & D < 0.5, 10000);                       // the first try's time out: a second
       !assert_true(markedFrom(D) & D < 0.5 & charging);
       !until(not charging, 10000);                                  // no nearer on it: given up, resumed
       !assert_false(charging);
       -+tripTimeout(150000).

// a way back round a wall goes away from the marked point first: tried again when its time runs out
// while the way left along the route map is markedProgress shorter than from the charger, given up once
// a try brought it no nearer along the route either
@[test]
+!test_a_way_back_nearer_along_the_route_is_tried_again_when_its_time_runs_out
    <- !until(not charging, 10000); !forget_calls; -markedTryFrom(_, _, _, _); -+tripTimeout(600);
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.1); -+battery(470);
       !!perceive(lowBattery);
       !until(.intend(reachCharger), 10000);
       -+location(-0.38, 0, 0.38); !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); -targetReached; !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       -+location(-0.5, 0, -0.3);                                    // 0.83 m -> 0.82 m from the mark in a straight line
       !until(markedTryFrom(0.3, -0.1, -0.5, -0.3), 10000);          // 2 m -> 1 m along the route: a second try
       !assert_true(markedTryFrom(0.3, -0.1, -0.5, -0.3) & charging);
       !until(not charging, 10000);                                  // 1 m -> 1 m on it: given up, resumed
       !assert_false(charging);
       -markedTryFrom(_, _, _, _); -+tripTimeout(150000).

// an agent whose task goes on from anywhere (tidy-up) resumes at the charger
@[test]
+!test_an_agent_that_resumes_at_the_charger_does_not_go_back_to_the_marked_point
    <- !until(not charging, 10000); +resumeAtCharger; !forget_calls;
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.1); -+battery(470);
       !!perceive(lowBattery);
       !until(.intend(reachCharger), 10000);
       !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); !!perceive(charged);
       !until(not charging, 10000);
       !assert_false(charging);
       !assert_false(mock_called(setUpTargetPoint(0.3, 0, -0.1)));  // no way back
       -resumeAtCharger.

// a low battery during a put-down: the trip waits until the robot is out of the storage area
// (@rechargeOutOfArea), and the way back ends where the battery went low (the low-battery episode's
// start, which the success criterion judges the return against), not where the trip began
@[test]
+!test_the_way_back_ends_where_the_battery_went_low_though_the_trip_began_later
    <- !until(not charging, 10000); !forget_calls;
       -lowBattery; -targetReached; -charged; +insideArea; +~delivered;
       -+location(0.45, 0, -0.4); -+battery(470);
       !!perceive(lowBattery);
       .wait(300);
       !assert_false(charging);                                      // the put-down first
       -insideArea; -~delivered; -+location(0.3, 0, -0.3); -+battery(465);
       -lowBattery; !!perceive(lowBattery);                          // out of the area: the trip
       !until(.intend(reachCharger), 10000);
       -+location(-0.38, 0, 0.38); !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); -targetReached; !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       !assert_true(mock_called(setUpTargetPoint(0.45, 0, -0.4)));   // where the battery went low
       !assert_false(mock_called(setUpTargetPoint(0.3, 0, -0.3)));
       !assert_true(mock_called(mark(0.45, 0, -0.4)));                // and the middleware marks it
       !assert_false(mock_called(mark(0.3, 0, -0.3)));
       -targetReached; !!perceive(targetReached);
       !until(not charging, 10000);
       !assert_false(charging).

// the last cylinder of a task that ends at the charger is delivered first wherever the robot is
@[test]
+!test_an_agent_that_delivers_first_delivers_the_last_cylinder_before_the_trip
    <- !until(not charging, 10000); +deliverFirst(300); +~delivered; +cylinders(2); -+stored(1); !forget_calls;
       -lowBattery; -targetReached; -charged; -+location(-0.3, 0, 0.3); -+battery(470);  // nearer the charger
       !!perceive(lowBattery); .wait(300);
       !assert_false(charging);
       !assert_false(mock_called(mark(_, _, _)));
       // 80 J over the reserve no longer cover the 2.1 m to the storage point and the charger: the trip
       -lowBattery; -+battery(380); !!perceive(lowBattery);
       !until(.intend(reachCharger), 10000);
       !assert_true(charging);
       -targetReached; !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); -charged; !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       -targetReached; !!perceive(targetReached);
       !until(not charging, 10000);
       -lowBattery; -+stored(0); -cylinders(2); -~delivered; -deliverFirst(300).

// a delivery that went on first keeps on while the battery less deliverOn's reserve covers the way
// via the storage point to the charger (a drain has come); under it, the trip
@[test]
+!test_a_delivery_that_went_on_first_keeps_on_after_a_drain_under_the_smaller_reserve
    <- !until(not charging, 10000); +deliverFirst(300); +deliverOn(50); +~delivered; -+lastFound(1); !forget_calls;
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.3); -+battery(470);   // 1.27 m: 64 J
       !!perceive(lowBattery); .wait(300);
       !assert_false(charging);
       !assert_true(deliveringFirst(1));                            // picked at 1
       -lowBattery; -+battery(200); !!perceive(lowBattery); .wait(300);   // a drain: 150 J over 50 cover it
       !assert_false(charging);
       !assert_false(mock_called(mark(_, _, _)));
       -lowBattery; -+battery(100); !!perceive(lowBattery);              // 50 J over it do not
       !until(.intend(reachCharger), 10000);
       !assert_true(charging);
       -targetReached; !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); -charged; !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       -targetReached; !!perceive(targetReached);
       !until(not charging, 10000);
       -lowBattery; -~delivered; -deliverOn(50); -deliverFirst(300); .abolish(deliveringFirst(_)).

// a task that ends at a known time (tidy-up) makes no trip while the battery covers the time left
// at full power (2.5 W): 470 J cover 100 s, not 300 s
@[test]
+!test_no_trip_while_the_battery_covers_the_time_left
    <- !until(not charging, 10000); !forget_calls;
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.1); -+battery(470);
       .system_time(T); +taskEnd(T + 100000);
       !!perceive(lowBattery); .wait(300);
       !assert_false(charging);
       !assert_false(mock_called(mark(_, _, _)));
       -taskEnd(_); .system_time(T2); +taskEnd(T2 + 300000);                 // 300 s left: the trip
       -lowBattery; !!perceive(lowBattery);
       !until(.intend(reachCharger), 10000);
       !assert_true(charging);
       -taskEnd(_); -targetReached; !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); -charged; !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       -targetReached; !!perceive(targetReached);
       !until(not charging, 10000);
       -lowBattery.

// an agent that believes meanPower(W) (tidy-up: 2 W) sums the time left at that power, not at full
// power: 470 J cover 200 s at 2 W (400 J), not at 2.5 W (500 J)
@[test]
+!test_an_agents_mean_power_makes_the_sum_of_the_time_left
    <- !until(not charging, 10000); +meanPower(2); !forget_calls;
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.1); -+battery(470);
       .system_time(T); +taskEnd(T + 200000);
       !!perceive(lowBattery); .wait(300);
       !assert_false(charging);
       !assert_false(mock_called(mark(_, _, _)));
       -meanPower(2); -lowBattery; !!perceive(lowBattery);              // at full power: the trip
       !until(.intend(reachCharger), 10000);
       !assert_true(charging);
       -taskEnd(_); -targetReached; !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(950); -charged; !!perceive(charged);
       !until(.intend(reachMarked), 10000);
       -targetReached; !!perceive(targetReached);
       !until(not charging, 10000);
       -lowBattery.

// an agent that charges only for the time left (tidy-up: chargeUntilLasts) leaves the charger once
// the battery less the reserve covers the task's time left at full power, short of the charged level
@[test]
+!test_the_charge_ends_once_the_battery_covers_the_time_left
    <- !until(not charging, 10000); +chargeUntilLasts(100); !forget_calls;
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.1); -+battery(470);
       .system_time(T); +taskEnd(T + 300000);                        // 300 s left: 750 J at 2.5 W
       !!perceive(lowBattery);
       !until(.intend(reachCharger), 10000);
       -targetReached; !!perceive(targetReached);
       !until(.intend(waitCharged), 10000);
       -+battery(800); .wait(300);
       !assert_true(.intend(waitCharged));                           // 700 J over the reserve: not yet
       -+battery(870);                                               // 770 J: enough, no "charged"
       !until(.intend(reachMarked), 10000);
       !assert_true(.intend(reachMarked));
       -targetReached; !!perceive(targetReached);
       !until(not charging, 10000);
       -taskEnd(_); -chargeUntilLasts(100); -lowBattery.

// an agent that delivers first (tidy-up) ends a delivery under way nearer the storage point than
// the charger before the trip; once it is over, the next lowBattery starts the trip
@[test]
+!test_an_agent_that_delivers_first_goes_to_the_charger_once_the_delivery_is_over
    <- !until(not charging, 10000); +deliverFirst(300); +~delivered; !forget_calls;
       -lowBattery; -targetReached; -charged; -+location(0.3, 0, -0.3); -+battery(470);
       !!perceive(lowBattery); .wait(300);
       !assert_false(charging);                                      // the storage point is nearer
       !assert_false(mock_called(mark(_, _, _)));
       -lowBattery; -~delivered; !!perceive(lowBattery);             // delivered: the trip
       !until(charging, 2000);
       !assert_true(charging);
       -deliverFirst(300).

// on the charger nothing turns the robot: a re-alignment begun as the charger was reached drove it
// off the charger mid-charge
@[test]
+!test_no_turn_on_the_charger
    <- +atCharger; -+desired(0); -+orientation(90); !forget_calls;
       !!balance; .wait(300);
       !assert_true(mock_called(stop));
       !assert_false(mock_called(setSpeeds(_, _)));
       .drop_intention(balance); -atCharger.

// after the put-down, in the storage area, facing a wall of its corner (a low battery waits for the
// way out: @rechargeOutOfArea): no progress there turns the robot to the arena's centre
// (storage-exit.asl), where it drove into the wall until the battery was empty (wide world 268)
@[test]
+!test_no_progress_after_the_put_down_turns_the_robot_out_of_the_storage_corner
    <- !until(not charging, 10000); !forget_calls; -delivering; -picking; -+orientation(90);
       +insideArea; +~delivered; -+location(0.47, 0, -0.47);
       !!perceive(stuck);
       !until(mock_called(forward), 5000);
       !assert_true(mock_called(computeAngle(0.47, -0.47, 0, 0, _)));   // towards the centre
       !assert_true(mock_called(forward));
       -insideArea; -~delivered; -stuck.

// a cylinder knocked out of the gripper by the storage area may be picked there just after the fall
// (knock-fetch.asl, as navigation and tidy-up): it lay within the storage clearance, never picked again
@[test]
+!test_a_cylinder_knocked_out_by_the_storage_area_may_be_picked_there
    <- ?location(X0, Y0, Z0); -+location(0.41, 0, -0.31);   // 0.1 m from the storage point
       -fellNearStorageAt(_);
       !assert_true(fallenNearStorage);
       .system_time(T); +fellNearStorageAt(T);
       !assert_true(fetchingKnocked);
       -fellNearStorageAt(_); -+location(X0, Y0, Z0).


// the search heads for look points (look-points.asl, lookSpacing(1.0): in this 1 x 1 m arena the one
// grid point, its centre), as navigation's, not for the lanes' ends at the arena's sides
@[test]
+!test_the_search_heads_for_look_points
    <- -sweep(_); -waypoint(_, _, _); -+location(-0.3, 0, 0.3);
       !planSweep;
       !assert_true(waypoint(0, 0, _)).

// a search whose round of look points is gone (a goal ended look-points' @newLookRound between
// forgetting the round's end and planning the next) plans a new round (look-points' @lookRoundLost)
@[test]
+!test_a_search_whose_round_is_gone_plans_a_new_one
    <- -sweep(_); -waypoint(_, _, _); -+location(-0.3, 0, 0.3); +searching;
       !nextWaypoint;
       !assert_true(waypoint(0, 0, _));
       -searching.
