// Skill tests of one robot at a time at the storage point (skills/team-storage.asl, in
// team-delivery.asl): a robot with a cylinder asks its turn near the storage point, stops and waits
// if another robot has it, and gives the turn up once 0.3 m out of the area (the area as the agent
// sees it: storageClearance, 0.19 m here), not while it still turns to leave. Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(1.0, 1.0).
storagePoint(0.41, -0.41).
storageRadius(0.1).
charger(-0.38, 0.38).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(computeAngle(_, _, _, _, 90), ok).
mock_operation(_, ok).

@[test]
+!test_far_from_the_storage_point_no_turn_is_asked
    <- +orientation(90); +storageQueue([]); +delivering; !forget_calls;
       !!perceive(location(0.0, 0, 0.0));                        // 0.58 m away
       .wait(200);
       !assert_false(mock_called(awaitStorageTurn));
       !assert_false(waitingStorage).

@[test]
+!test_a_robot_waits_for_its_turn_while_another_is_at_the_storage_point
    <- !forget_calls; -+storageQueue([khepera2]);
       -location(_, _, _); !!perceive(location(0.2, 0, -0.3));   // 0.24 m away
       !until(storageTurnMine, 5000);
       !assert_true(mock_called(stop));                          // stopped, then waited
       !assert_true(mock_called(awaitStorageTurn));
       !assert_false(waitingStorage).

@[test]
+!test_the_turn_is_given_up_only_away_from_the_area
    <- !forget_calls; +insideArea; -insideArea;                   // out of the area
       -location(_, _, _); !!perceive(location(0.25, 0, -0.3));    // 0.19 m from the point: still turning to leave
       .wait(400);
       !assert_false(mock_called(storageDone));                    // the next robot is not let in yet
       !assert_true(storageTurnMine);
       -location(_, _, _); !!perceive(location(0.0, 0, -0.3));     // 0.42 m: 0.23 m out of the area
       .wait(300);
       !assert_false(mock_called(storageDone));
       -location(_, _, _); !!perceive(location(0.0, 0, -0.1));     // 0.51 m: 0.32 m out
       !until(mock_called(storageDone), 5000);
       !assert_true(mock_called(storageDone));
       !assert_false(storageTurnMine).

@[test]
+!test_a_free_storage_point_is_taken_without_stopping
    <- !forget_calls; -+storageQueue([]);
       -location(_, _, _); !!perceive(location(0.21, 0, -0.3));
       !until(storageTurnMine, 5000);
       !assert_true(mock_called(awaitStorageTurn));
       !assert_false(mock_called(stop)).

@[test]
+!test_an_earlier_turns_watch_does_not_end_a_later_turn
    <- !forget_calls; -storageTurnMine; -+storageTurnLimit(600);
       !storageTurnTaken; .wait(300);
       !giveStorageTurn; !storageTurnTaken;                      // the next turn, 300 ms later
       .wait(450);                                                // the first turn's watch is over
       !assert_true(storageTurnMine);
       !until(not storageTurnMine, 3000);                        // the second turn's watch ends it
       !assert_false(storageTurnMine);
       -+storageTurnLimit(60000).

@[test]
+!test_no_progress_after_the_put_down_turns_the_robot_to_the_arenas_centre
    <- !forget_calls; -delivering; -picking; -waitingStorage; -+orientation(90);
       +insideArea; -location(_, _, _); +location(0.47, 0, -0.47);   // beyond the point, in the corner
       !!perceive(stuck);
       !until(mock_called(forward), 5000);
       !assert_true(mock_called(computeAngle(0.47, -0.47, 0, 0, _)));   // towards the centre
       !assert_true(desired(90));
       !assert_true(mock_called(forward));
       -insideArea; -stuck.

// the holder clears out while a teammate waits for its turn: a quick half turn, then straight off
@[test]
+!test_the_half_turn_is_quick_only_while_a_teammate_waits
    <- .my_name(Me); +storageTurnMine; -+storageQueue([Me]);
       !assert_false(quickTurn(_, _));
       -+storageQueue([Me, khepera2]);
       !assert_true(quickTurn(50, 15));
       -storageTurnMine; -+storageQueue([]).

@[test]
+!test_the_way_off_leads_away_from_the_storage_point_and_the_teammate_waiting
    <- .my_name(Me); +storageTurnMine; -+storageQueue([Me, khepera2]);
       -location(_, _, _); +location(0.25, 0, -0.3);              // out of the area, towards the arena's centre
       -+robotAt(khepera2, 0.1, -0.41);                           // waiting on the robot's left
       ?clearOutTo(Tx, Tz);
       !assert_true(Tz > 0.5 & Tx > 0.15 & Tx < 0.35);          // square to both: neither nearer
       -+robotAt(khepera2, 0.085, -0.187);                        // waiting straight ahead on the way out
       ?clearOutTo(Ux, Uz);
       !assert_true(Ux > 0.7 & Uz > 0.45);                       // aside, on the arena centre's side
       -robotAt(khepera2, _, _); -storageTurnMine; -+storageQueue([]).

@[test]
+!test_out_of_the_area_a_holder_with_a_teammate_waiting_drives_off_instead_of_looking_around
    <- .my_name(Me); +storageTurnMine; -+storageQueue([Me, khepera2]); -+orientation(90);
       -location(_, _, _); +location(0.25, 0, -0.3); -+robotAt(khepera2, 0.1, -0.41);
       +storageLeaving(0); -+lastLook(-100000); !forget_calls;
       !sweepStep;
       !assert_true(mock_called(computeAngle(0.25, -0.3, _, _, _)));
       !assert_true(mock_called(setSpeeds(100, 100)));
       !assert_false(mock_called(setSpeeds(-50, 50)));          // no look around
       -storageLeaving(_); -storageTurnMine; -robotAt(khepera2, _, _); -+storageQueue([]).

// the way off keeps off the arena's walls: near one, its part towards the wall is dropped; in the
// corner beyond the storage point, the arena's centre
@[test]
+!test_the_way_off_keeps_off_the_walls
    <- .my_name(Me); +storageTurnMine; -+storageQueue([Me, khepera2]);
       -location(_, _, _); +location(0.41, 0, -0.2);               // 0.09 m from the east wall
       -+robotAt(khepera2, 0.2, -0.41);                           // waiting west of the storage point
       ?clearOutTo(Tx, Tz);
       !assert_true(Tx < 0.42 & Tz > 1);                          // along the wall, not into it (0.71 m east unkept)
       -location(_, _, _); +location(0.45, 0, -0.45);              // beyond the point, in the corner
       ?clearOutTo(Cx, Cz);
       !assert_true(Cx == 0 & Cz == 0);
       -robotAt(khepera2, _, _); -storageTurnMine; -+storageQueue([]).

// the timeout came before the holder was away: the look around is made inside the turn, then the turn given up
@[test]
+!test_a_look_around_due_at_the_timeout_is_made_inside_the_turn
    <- .my_name(Me); +storageTurnMine; -+storageQueue([Me, khepera2]); +searching;
       -location(_, _, _); +location(0.25, 0, -0.3); -+robotAt(khepera2, 0.1, -0.41);
       -+lastLook(-100000); +storageLeaving(-100000); !forget_calls;
       -location(_, _, _); !!perceive(location(0.26, 0, -0.3));   // 0.17 m from the point, the timeout long past
       !until(lookInTurn(_), 3000);
       !assert_false(storageLeaving(_));
       !assert_true(storageTurnMine);                             // kept for the look
       !assert_false(mock_called(storageDone));
       !sweepStep;
       !assert_true(mock_called(setSpeeds(-50, 50)));           // the look around
       !assert_true(mock_called(storageDone));                   // then the turn given up
       !assert_false(storageTurnMine);
       -searching; -robotAt(khepera2, _, _); -+storageQueue([]).

// out of the area on the far side of the storage point from the teammate waiting: the turn is handed
// over at once, and the holder still clears out; on the teammate's side it is kept
@[test]
+!test_the_turn_is_handed_over_early_only_from_the_far_side
    <- .my_name(Me); +storageTurnMine; -+storageQueue([Me, khepera2]); -+orientation(90);
       -+robotAt(khepera2, 0.1, -0.41);                           // waiting west of the storage point
       .system_time(T); +storageLeaving(T); !forget_calls;
       -location(_, _, _); !!perceive(location(0.25, 0, -0.3));   // out, on the teammate's side
       .wait(400);
       !assert_false(mock_called(storageDone));
       !assert_true(storageTurnMine);
       -location(_, _, _); !!perceive(location(0.45, 0, -0.25));  // out, beyond the point from it
       !until(mock_called(storageDone), 3000);
       !assert_false(storageTurnMine);
       !assert_true(handedOverTo(khepera2));
       !assert_true(storageLeaving(_));                           // still clearing out
       !forget_calls; -+lastLook(-100000);
       !sweepStep;
       !assert_true(mock_called(setSpeeds(100, 100)));
       !assert_false(mock_called(setSpeeds(-50, 50)));          // no look around yet
       -storageLeaving(_); -handedOverTo(_); -robotAt(khepera2, _, _); -+storageQueue([]).

// a holder back in the area with another cylinder (picked beside it while the turn was still held):
// the first leaving's timeout, long past, does not give the turn up while it puts this one down
@[test]
+!test_a_holder_back_in_the_area_keeps_its_turn_past_the_leaving_timeout
    <- .my_name(Me); +storageTurnMine; -+storageQueue([Me, khepera2]); -+robotAt(khepera2, 0.1, -0.41);
       +storageLeaving(-100000); +delivering; !forget_calls;
       +insideArea;                                               // came in again
       -location(_, _, _); !!perceive(location(0.38, 0, -0.38));  // at the storage point
       .wait(400);
       !assert_false(mock_called(storageDone));
       !assert_true(storageTurnMine);
       !assert_false(storageLeaving(_));
       -delivering; -insideArea;                                  // out again: the leaving starts anew
       !assert_true(storageLeaving(_));
       -storageLeaving(_); -storageTurnMine; -robotAt(khepera2, _, _); -+storageQueue([]).
