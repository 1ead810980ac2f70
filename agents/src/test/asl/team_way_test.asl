// Skill tests of the right of way between teammates (skills/team-way.asl, in team-delivery.asl):
// the robot whose name comes later gives way to a teammate too close (steps aside from one ahead:
// a turn away from it, then forward), the earlier one goes on, and stops a moment while the other
// is right ahead of it when it drives on its way; a teammate standing in the storage area's queue is given way whatever
// its name, the one whose turn it is before every other, and a robot that would push a teammate
// ahead by moving on steps aside from it instead; a robot waiting for the charger gives
// way, one on it does not; a robot that waits does not cruise; a robot giving way publishes its place
// meanwhile, and moves on from a teammate behind at the speed of travel. The agent under test is named
// team_way_test: khepera1 comes before it, zeta after it.
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
+!test_the_later_name_steps_aside_from_a_teammate_ahead
    <- !forget_calls; +location(0.1, 0, 0.2); +orientation(90); +storageQueue([]); +chargerQueue([]);
       !!perceive(robotAt(khepera1, 0.12, 0.3));         // 10 cm ahead, a little to the lesser angle, an earlier name
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(L, R)) & L > 0 & R == -L);   // turns away from it (the heading grows)
       !assert_true(mock_called(setSpeeds(V, V)) & V > 0);             // then goes on, out of its line
       !assert_false(givingWay);
       -robotAt(khepera1, _, _); !forget_calls;
       !!perceive(robotAt(khepera1, 0.08, 0.3));         // a little to the greater angle: the other way
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(L2, R2)) & L2 < 0 & R2 == -L2);
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
       !assert_true(mock_called(setSpeeds(L, R)) & L > 0 & L == R);     // moves on, away from it
       -robotAt(zeta, _, _); -storageQueue(_); +storageQueue([]).

@[test]
+!test_moving_on_would_push_a_teammate_ahead_so_the_robot_steps_aside_from_it
    <- !forget_calls; -storageQueue(_); +storageQueue([khepera1, zeta]);
       +robotAt(zeta3, 0.12, 0.3);                       // 10 cm ahead, a little to the lesser angle
       !!perceive(robotAt(zeta, 0.1, 0.1));              // 10 cm behind, waiting for the storage area
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(L, R)) & L > 0 & R == -L);    // turns away from the one ahead
       !assert_false(mock_called(setSpeeds(40, 40)));                   // does not move on into it
       -robotAt(zeta, _, _); -robotAt(zeta3, _, _); -storageQueue(_); +storageQueue([]).

@[test]
+!test_two_robots_in_a_queue_go_by_name
    <- !forget_calls; -storageQueue(_); +storageQueue([zeta2, team_way_test, khepera1]);
       !!perceive(robotAt(zeta, 0.1, 0.3));              // not queued: it gives way to this robot
       .wait(300);
       !assert_false(mock_called(setSpeeds(_, _)));
       -robotAt(zeta, _, _);
       !!perceive(robotAt(khepera1, 0.1, 0.3));          // queued too, an earlier name: this robot gives way
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(L, R)) & R == -L);
       -robotAt(khepera1, _, _); -storageQueue(_); +storageQueue([]).

@[test]
+!test_the_robot_whose_turn_it_is_goes_on_before_an_earlier_name
    <- !forget_calls; -storageQueue(_); +storageQueue([team_way_test, khepera1]);   // this robot's turn
       !!perceive(robotAt(khepera1, 0.1, 0.3));
       .wait(300);
       !assert_false(mock_called(setSpeeds(_, _)));
       -robotAt(khepera1, _, _); -storageQueue(_); +storageQueue([]).

@[test]
+!test_a_robot_waiting_for_the_charger_gives_way_to_the_one_whose_turn_it_is
    <- !forget_calls; -location(_, _, _); +location(-0.2, 0, 0.3); -chargerQueue(_);
       +chargerQueue([zeta, team_way_test]); +waitingCharger;
       !!perceive(robotAt(zeta, -0.2, 0.4));             // 10 cm ahead, on its way to the charger
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(L, R)) & R == -L);          // the waiting robot steps aside
       !assert_true(waitingCharger);                     // and still waits
       -robotAt(zeta, _, _); -waitingCharger; -chargerQueue(_); +chargerQueue([]);
       -location(_, _, _); +location(0.1, 0, 0.2).

@[test]
+!test_a_robot_on_the_charger_does_not_move_for_anyone
    <- !forget_calls; -location(_, _, _); +location(-0.38, 0, 0.38); -chargerQueue(_);
       +chargerQueue([zeta, team_way_test]); +atCharger;
       !!perceive(robotAt(zeta, -0.38, 0.48));
       .wait(300);
       !assert_false(mock_called(setSpeeds(_, _)));
       -robotAt(zeta, _, _); -atCharger; -chargerQueue(_); +chargerQueue([]);
       -location(_, _, _); +location(0.1, 0, 0.2).

@[test]
+!test_a_robot_that_starts_to_wait_stands_still_and_does_not_cruise
    <- !forget_calls; +waitingStorage;
       !cruise;                                          // a re-alignment ending while it waits
       !assert_true(mock_called(stop));
       !assert_false(mock_called(setSpeeds(_, _)));
       -waitingStorage; !forget_calls;
       !cruise;                                          // not waiting: it goes on
       !assert_true(mock_called(setSpeeds(_, _))).

@[test]
+!test_the_robot_with_the_right_of_way_stops_while_the_other_is_right_ahead
    <- !forget_calls; -location(_, _, _); +location(0.1, 0, 0.2); -orientation(_); +orientation(90);
       +delivering;                                      // on its way to the storage point
       !!perceive(robotAt(zeta, 0.1, 0.28));             // 8 cm ahead, a later name: it gives way
       !until(mock_called(stop), 3000);
       !until(mock_called(setSpeeds(_, _)), 3000);
       !assert_true(mock_called(setSpeeds(V, V)) & V > 0);   // a moment later it drives on
       -robotAt(zeta, _, _); !forget_calls;
       !!perceive(robotAt(zeta, 0.18, 0.2));             // 8 cm beside: not in its way
       .wait(300);
       !assert_false(mock_called(stop));
       -robotAt(zeta, _, _); -delivering; -stoppedFor(_, _).

// the teammate given way to stops for this robot by its place on the board: an atomic give-way
// publishes it as it goes (team-places' !waitPublishing), not only once it is over
@[test]
+!test_a_robot_giving_way_publishes_its_place_meanwhile
    <- .system_time(T0); -+placePublished(T0);           // just published: not due by the percept
       -location(_, _, _); +location(0.1, 0, 0.2); -orientation(_); +orientation(90);
       -storageQueue(_); +storageQueue([khepera1, zeta]); !forget_calls;
       !!perceive(robotAt(zeta, 0.1, 0.1));              // 10 cm behind, waiting: this robot moves on
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(V, V)) & V > 0);
       !assert_true(mock_called(at(0.1, 0.2)));          // published before the give-way was over
       -robotAt(zeta, _, _); -storageQueue(_); +storageQueue([]).

// a robot giving way to a teammate behind moves on at the speed that one comes on at, travelling
@[test]
+!test_a_robot_giving_way_to_one_behind_moves_on_at_the_speed_of_travel
    <- -location(_, _, _); +location(0.1, 0, 0.2); -orientation(_); +orientation(90);
       -storageQueue(_); +storageQueue([khepera1, zeta]); !forget_calls;
       !!perceive(robotAt(zeta, 0.1, 0.1));              // 10 cm behind, waiting: this robot moves on
       !until(mock_called(stop), 3000);
       !assert_true(mock_called(setSpeeds(V, V)) & travelSpeed(V));
       -robotAt(zeta, _, _); -storageQueue(_); +storageQueue([]).
