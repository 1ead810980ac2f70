// Skill tests of one charger for the team (skills/team-charger.asl, in team-delivery.asl): a
// robot with a low battery first goes near the charger and only there queues for it; once
// recharged it leaves the queue when it is away from the charger; a low battery while another robot
// has the charger books a place and the task goes on until its turn; with teammates, a low battery
// in the storage area waits until the robot is out of it. Run: jacabot test agents/src/test/asl
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
+!test_a_low_battery_takes_the_robot_near_the_charger_before_it_queues
    <- +location(0.3, 0, 0.2); +orientation(90); +battery(470); +chargerQueue([]);
       !!perceive(lowBattery);
       !until(mock_called(setThreshold(0.3)), 10000);
       !assert_true(mock_called(setUpTargetPoint(-0.38, 0, 0.38)));
       .wait(200);
       !assert_false(mock_called(awaitCharger));                 // not waiting at the charger while far
       -location(_, _, _); +location(-0.2, 0, 0.3);
       -targetReached; !!perceive(targetReached);                // near the charger
       !until(mock_called(awaitCharger), 10000);
       !assert_true(mock_called(requestCharger(470)));           // its need, then it waits there
       !until(mock_called(setThreshold(0.03)), 10000);
       !assert_true(mock_called(setThreshold(0.03))).            // then onto the charger itself

@[test]
+!test_a_recharged_robot_leaves_the_queue_once_away_from_the_charger
    <- !forget_calls;
       -location(_, _, _); +location(-0.38, 0, 0.38);
       -targetReached; !!perceive(targetReached);                // on the charger
       !until(.intend(waitCharged), 10000);
       -+battery(950); !!perceive(charged);
       .wait(600);
       !assert_false(mock_called(leaveCharger));                 // still on it
       -location(_, _, _); +location(-0.1, 0, 0.38);              // 0.28 m away: it still has its turn
       .wait(600);
       !assert_false(mock_called(leaveCharger));
       -location(_, _, _); +location(-0.04, 0, 0.38);             // 0.34 m away
       !until(mock_called(leaveCharger), 5000);
       !assert_true(mock_called(leaveCharger)).

@[test]
+!test_a_low_battery_while_another_has_the_charger_books_it_and_works_on
    <- !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked;
       -location(_, _, _); +location(0.3, 0, 0.2); -+battery(470); -chargerQueue(_); +chargerQueue([khepera9]);
       -lowBattery; !!perceive(lowBattery);
       !until(mock_called(requestCharger(470)), 5000);
       !assert_true(chargerBooked);
       -lowBattery; !!perceive(lowBattery); .wait(300);
       !assert_false(charging);                                  // no trip while another has its turn
       !assert_false(mock_called(setThreshold(0.3)));
       -chargerQueue(_); +chargerQueue([team_charger_test, khepera9]);   // its turn
       -lowBattery; !!perceive(lowBattery);
       !until(mock_called(setThreshold(0.3)), 5000);
       !assert_true(charging);                                   // the trip starts
       !assert_false(chargerBooked).

@[test]
+!test_the_robot_on_the_charger_leaves_early_for_a_needier_one_waiting_there
    <- !forget_calls; -location(_, _, _); +location(-0.38, 0, 0.38);
       -chargerQueue(_); +chargerQueue([team_charger_test, khepera9]); -chargerWaiting(_); +chargerWaiting([]);
       -targetReached; !!perceive(targetReached);                // near the charger: waits, its turn
       !until(mock_called(setThreshold(0.03)), 10000); .wait(300);
       -targetReached; !!perceive(targetReached);                // on the charger
       !until(.intend(waitCharged), 10000);
       !assert_true(.intend(waitCharged));
       -+battery(620); .wait(300);
       !assert_true(.intend(waitCharged));                       // nobody waits at the charger yet
       -chargerWaiting(_); +chargerWaiting([700]); -+battery(630); .wait(300);
       !assert_true(.intend(waitCharged));                       // the one waiting is not needier
       -chargerWaiting(_); +chargerWaiting([700, 400]); -+battery(640);
       !until(not .intend(waitCharged), 3000);
       !assert_false(.intend(waitCharged));                      // it gives the charger up at 640 J
       -chargerWaiting(_); +chargerWaiting([]).

@[test]
+!test_the_reserve_grows_with_the_way_to_the_charger_and_the_robots_ahead
    <- !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked;
       .drop_desire(rechargeTrip(_, _, _, _)); .drop_desire(backToTask(_, _, _, _));
       -chargerQueue(_); +chargerQueue([]);
       -location(_, _, _); +location(-0.28, 0, 0.38);            // 0.1 m from the charger
       !assert_true(chargerReserveNow(R1) & R1 < 120);
       -location(_, _, _); +location(1.62, 0, 0.38);             // 2 m away
       !assert_true(chargerReserveNow(R2) & R2 > 240);
       -chargerQueue(_); +chargerQueue([khepera9, khepera8, team_charger_test]);
       !assert_true(chargerReserveNow(R3) & R3 > R2 + 40);       // two robots ahead
       -+battery(280); -lowBattery; !!perceive(lowBattery);       // 280 J is below it: the trip starts
       !until(charging, 5000);
       !assert_true(charging);
       !assert_false(chargerBooked).

@[test]
+!test_a_detour_begun_on_the_way_ends_on_the_charger
    <- !forget_calls; -atCharger; -avoiding;
       !!pretendDetour;                                           // a detour under way (forward, then re-align)
       !until(.intend(detour(_)), 3000);
       +atCharger;                                                // the robot is on the charger
       .wait(300);                                                // a detour lasts a second at least
       !assert_false(.intend(detour(_)));
       !assert_false(avoiding);
       -atCharger.

+!pretendDetour <- !detour(1).

// a delivery under way nearer the storage point than the free charger ends first (deliverFirst)
@[test]
+!test_a_delivery_near_the_storage_point_ends_before_the_trip
    <- !until(not charging, 10000); !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked;
       -chargerQueue(_); +chargerQueue([]); +~delivered;
       -location(_, _, _); +location(0.3, 0, -0.3); -+battery(470);      // 0.16 m from the storage point
       -lowBattery; !!perceive(lowBattery); .wait(300);
       !assert_false(charging);
       !assert_false(mock_called(mark(_, _, _)));
       -~delivered; -lowBattery; !!perceive(lowBattery);                  // delivered: the trip
       !until(charging, 3000);
       !assert_true(charging).

// a low battery in the storage area: with teammates the area is left first (the trip starts once
// out of it); alone, the trip starts at once, as before
@[test]
+!test_a_low_battery_in_the_storage_area_waits_until_the_robot_is_out
    <- !until(not charging, 10000); !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked; -~delivered;
       -chargerQueue(_); +chargerQueue([]); +robotAt(khepera9, -0.4, -0.4);
       -location(_, _, _); +location(0.4, 0, -0.4); -+battery(470); +insideArea;
       -lowBattery; !!perceive(lowBattery); .wait(300);
       !assert_false(charging);
       -insideArea; -lowBattery; !!perceive(lowBattery);                  // out of the area: the trip
       !until(charging, 3000);
       !assert_true(charging);
       .drop_desire(rechargeTrip(_, _, _, _)); .drop_desire(balance); -charging;
       -robotAt(khepera9, _, _); +insideArea;                              // alone: the trip at once
       -lowBattery; !!perceive(lowBattery);
       !until(charging, 3000);
       !assert_true(charging);
       .drop_desire(rechargeTrip(_, _, _, _)); .drop_desire(balance); -charging; -insideArea.

// the charger tried again after a timeout: an obstacle met while the robot re-aligns (heading's
// detour drops every intention with a balance goal) must not drop the trip itself
@[test]
+!test_an_obstacle_while_trying_the_charger_again_keeps_the_trip
    <- !until(not charging, 10000); !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked; -~delivered;
       -chargerQueue(_); +chargerQueue([]); -+tripTimeout(400); -+delta(300); -obstacle(_);
       -location(_, _, _); +location(0.3, 0, 0.2); -+orientation(0); -+battery(470);
       -lowBattery; !!perceive(lowBattery);
       !until(.intend(escape), 5000);                             // the charger not reached in time
       !until(not .intend(escape), 5000);                         // escaped: re-aligning to the charger
       .wait(100);
       !!perceive(obstacle(true));                                // an obstacle on the way
       .wait(500);
       !assert_true(.intend(rechargeTrip(0.3, 0, 0.2, 0)));       // the trip goes on
       -obstacle(true); -+tripTimeout(150000); -+orientation(90);
       .drop_desire(rechargeTrip(_, _, _, _)); .drop_desire(balance); .drop_desire(detour(_)); -charging.

// the robot whose turn it is but that comes no nearer the charger lets one waiting there go first
@[test]
+!test_a_turn_holder_that_comes_no_nearer_lets_the_one_waiting_go_first
    <- !until(not charging, 10000); !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked; -~delivered;
       -+chargerProgressTime(800); -+tripTimeout(150000);
       -chargerQueue(_); +chargerQueue([]); -chargerWaiting(_); +chargerWaiting([]);
       -location(_, _, _); +location(-0.2, 0, 0.3); -+orientation(90); -+battery(470);   // near the charger
       -lowBattery; !!perceive(lowBattery);
       !until(mock_called(setThreshold(0.03)), 5000);             // its turn: on to the charger
       -chargerQueue(_); +chargerQueue([team_charger_test, khepera9]);
       -chargerWaiting(_); +chargerWaiting([300]);                 // another robot waits there
       .wait(200);
       !assert_false(mock_called(yieldCharger));
       !until(mock_called(yieldCharger), 3000);                   // no nearer after 0.8 s: it yields
       !assert_true(mock_called(yieldCharger));
       -+chargerProgressTime(12000); -chargerWaiting(_); +chargerWaiting([]);
       .drop_desire(rechargeTrip(_, _, _, _)); .drop_desire(balance); -charging; -yieldedCharger; -waitingCharger.

// the battery covers the run's time left (taskEnd, told by the team's runner): no place is booked,
// and a place booked earlier is given back (a robot heading the queue that never came kept its
// teammates booked and working on behind it until their reserve)
@[test]
+!test_a_battery_that_lasts_to_the_end_books_nothing_and_gives_a_booking_back
    <- !until(not charging, 10000); !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked; -~delivered;
       -chargerQueue(_); +chargerQueue([khepera9]); -robotAt(_, _, _);
       -location(_, _, _); +location(0.3, 0, 0.2); -+battery(470);
       .system_time(T); +taskEnd(T + 100000);                         // 100 s left: 250 J at 2.5 W
       -lowBattery; !!perceive(lowBattery); .wait(300);
       !assert_false(mock_called(requestCharger(470)));                // nothing booked
       !assert_false(charging);
       -taskEnd(_); .system_time(T2); +taskEnd(T2 + 300000);           // 300 s left: 750 J
       -lowBattery; !!perceive(lowBattery);
       !until(chargerBooked, 3000);
       !assert_true(mock_called(requestCharger(470)));                 // booked, working on
       -taskEnd(_); .system_time(T3); +taskEnd(T3 + 100000);           // the run nears its end
       -lowBattery; !!perceive(lowBattery);
       !until(mock_called(leaveCharger), 3000);
       !assert_true(mock_called(leaveCharger));                        // the place given back
       !assert_false(chargerBooked);
       -chargerQueue(_); +chargerQueue([team_charger_test, khepera9]); // it would head the queue now
       -lowBattery; !!perceive(lowBattery); .wait(300);
       !assert_false(charging);                                        // and no trip
       -taskEnd(_); -chargerQueue(_); +chargerQueue([]); -lowBattery.

// another robot is queued, but the battery at chargerShare does not cover the run's time left: the
// charge goes on (a second trip before the end cost more than the teammate's wait), and is shared
// once it covers it
@[test]
+!test_a_shared_charge_goes_on_while_the_time_left_needs_it
    <- !until(not charging, 10000); !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked; -~delivered;
       -location(_, _, _); +location(-0.38, 0, 0.38); -+battery(470);
       -chargerQueue(_); +chargerQueue([team_charger_test, khepera9]); -chargerWaiting(_); +chargerWaiting([]);
       .system_time(T); +taskEnd(T + 400000);                         // 400 s left: 1000 J at 2.5 W
       -lowBattery; !!perceive(lowBattery);
       !until(mock_called(setThreshold(0.03)), 10000); .wait(300);
       -targetReached; !!perceive(targetReached);                     // on the charger
       !until(.intend(waitCharged), 10000);
       -+battery(760); .wait(300);
       !assert_true(.intend(waitCharged));                            // queued behind it, but 760 J do not last
       -taskEnd(_); .system_time(T2); +taskEnd(T2 + 200000);          // 200 s left: 500 J
       -+battery(770);
       !until(not .intend(waitCharged), 3000);
       !assert_false(.intend(waitCharged));                           // shared now
       -taskEnd(_); -chargerQueue(_); +chargerQueue([]).

// with teammates a recharged robot drives off at once, away from the charger's corner and the
// teammate waiting beside it, leaves the queue 0.15 m off, drives on out of 0.3 m, and goes on from
// there without turning back to the heading it had when its battery went low
@[test]
+!test_with_teammates_a_recharged_robot_drives_off_and_leaves_the_queue_on_the_way
    <- !until(not charging, 10000); !forget_calls; -charging; -atCharger; -waitingCharger; -chargerBooked; -~delivered;
       -chargerQueue(_); +chargerQueue([]); -chargerWaiting(_); +chargerWaiting([]);
       -location(_, _, _); +location(-0.3, 0, 0.3); -+orientation(45); -+battery(470);
       -lowBattery; !!perceive(lowBattery);
       !until(mock_called(setThreshold(0.03)), 10000); .wait(300);
       -location(_, _, _); +location(-0.38, 0, 0.38);
       -targetReached; !!perceive(targetReached);                     // on the charger
       !until(.intend(waitCharged), 10000);
       +robotAt(khepera9, -0.2, 0.38);                                // a teammate waits on its +x side
       !forget_calls; -+battery(950); -charged; !!perceive(charged);
       !until(leavingCharger, 3000);
       !assert_true(targetPoint(Tx, Tz) & math.abs(Tx + 0.38) < 0.01 & math.abs(Tz + 0.02) < 0.01); // along the -x wall
       -location(_, _, _); +location(-0.38, 0, 0.27); .wait(400);
       !assert_false(mock_called(leaveCharger));                      // 0.11 m off: still its turn
       -location(_, _, _); +location(-0.38, 0, 0.2);
       !until(mock_called(leaveCharger), 3000);
       !assert_true(mock_called(leaveCharger));                       // 0.18 m off: the queue left
       !assert_true(leavingCharger);                                  // still driving off
       -location(_, _, _); +location(-0.38, 0, 0.05);                 // out of 0.3 m
       !until(not charging, 3000);
       !assert_false(charging);
       !assert_false(leavingCharger);
       !assert_true(desired(90));                                     // not the marked 45 degrees
       -robotAt(khepera9, _, _); -+orientation(90).

// with teammates the time left is reckoned at teamMeanPower (2 W), not at the wheels' full 2.5 W,
// and a charge ends once the battery less teamChargeReserve covers it; alone, as before
@[test]
+!test_with_teammates_the_time_left_is_reckoned_at_the_mean_power_and_a_charge_ends_once_it_covers_it
    <- -robotAt(_, _, _); -taskEnd(_); .system_time(T); +taskEnd(T + 300000); -+battery(720);  // 300 s left
       .system_time(T1);
       !assert_false(batteryLasts(T1));                 // alone: 720 J against 750 J at 2.5 W
       !assert_false(chargedEnough);                    // and charged only at chargedLevel
       +robotAt(khepera9, -0.4, -0.4);
       .system_time(T2);
       !assert_true(batteryLasts(T2));                  // a teammate: 720 J against 600 J at 2 W
       !assert_true(chargedEnough);                     // 620 J over the reserve covers it
       -+battery(650);
       !assert_false(chargedEnough);                    // 550 J does not
       -robotAt(khepera9, _, _); -taskEnd(_); -+battery(470).

@[test]
+!test_a_no_progress_signal_just_after_a_wait_at_the_charger_is_the_waits
    <- !until(not charging, 10000); !forget_calls; -avoiding; -waitingCharger;
       .system_time(Now); -+chargerWaitOver(Now - 500);           // its turn came 0.5 s ago
       !!perceive(stuck);
       !until(not chargerWaitOver(_), 3000);
       !assert_false(chargerWaitOver(_));                         // taken as the wait's
       !assert_false(avoiding);                                   // no escape
       !assert_false(mock_called(stop)).
