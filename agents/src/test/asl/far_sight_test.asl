// Skill test of far sight (skills/far-sight.asl): a cylinder sighted far off makes the robot turn
// towards it on the spot when it is well to a side, or steer towards it on the way (faster when it
// is far); it is given up after homingGiveUp and ignored a while; random motion waits while it stays
// in sight and looks elsewhere once it is lost. The operations are mocked (agents/README.md
// "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/far-sight.asl") }

maxSpeed(100).
reachCylinder(false).   // picking's
mock_operation(_, ok).

// recovery's escape
+!escape <- +escaped.

// a new sighting percept (the previous one gone)
+!sighting(Off, Dist) <- .abolish(cylinderSighted(_, _)); !!perceive(cylinderSighted(Off, Dist)).

@[test]
+!test_set_up_starts_the_camera_scan
    <- !forget_calls; !setUpFarSight;
       !assert_true(mock_called(scanForCylinders(400, 60))).

@[test]
+!test_a_cylinder_well_to_the_right_is_turned_to_on_the_spot
    <- !forget_calls; -homing(_); !sighting(20, 1.0);
       !until(mock_called(setSpeeds(_, _)), 2000);
       !assert_true(homing(_));
       !assert_true(mock_called(setSpeeds(25, -25))).

@[test]
+!test_a_far_cylinder_ahead_is_steered_to_at_travel_speed
    <- !forget_calls; !sighting(4, 1.0);
       !until(mock_called(setSpeeds(_, _)), 2000);
       !assert_true(mock_called(setSpeeds(94, 86))).

@[test]
+!test_a_near_cylinder_ahead_is_approached_slowly
    <- !forget_calls; !sighting(-4, 0.3);
       !until(mock_called(setSpeeds(_, _)), 2000);
       !assert_true(mock_called(setSpeeds(36, 44))).

// tidy-up's quickApproach(V): the same near approach at V
@[test]
+!test_a_quick_approach_takes_the_near_cylinder_at_its_speed
    <- !forget_calls; +quickApproach(85); !sighting(-4, 0.3);
       !until(mock_called(setSpeeds(_, _)), 2000);
       -quickApproach(85);
       !assert_true(mock_called(setSpeeds(81, 89))).

@[test]
+!test_no_homing_while_picking
    <- !forget_calls; -homing(_); +picking; !sighting(0, 1.0);
       .wait(300); -picking;
       !assert_false(homing(_));
       !assert_false(mock_called(setSpeeds(_, _))).

// another skill's sightingOff(Off, Dist) leaves a sighting alone (search-memory: the stored pile)
sightingOff(Off, Dist) :- offSighting(Off, Dist).
@[test]
+!test_a_sighting_another_skill_takes_off_is_not_homed_on
    <- !forget_calls; -homing(_); +offSighting(0, 0.6); !sighting(0, 0.6);
       .wait(300);
       !assert_false(homing(_));
       !assert_false(mock_called(setSpeeds(_, _)));
       -offSighting(0, 0.6); !sighting(0, 0.6);          // the same sighting, not taken off
       !until(homing(_), 2000);
       !assert_true(sightOffset(0));
       -homing(_).

@[test]
+!test_a_cylinder_chased_too_long_is_given_up_and_ignored_a_while
    <- !forget_calls; -escaped; .system_time(T); -+homing(T - 60000); -+ignoreFor(1500);  // a minute; ignored 1.5 s, long enough for a loaded machine
       !sighting(0, 1.0);
       !until(escaped, 2000);
       !assert_false(homing(_));
       !assert_true(escaped);
       !assert_true(ignoring);
       !sighting(0, 1.0); .wait(100);
       !assert_false(homing(_));                                       // ignored meanwhile
       !until(not ignoring, 6000);
       !assert_false(ignoring).

@[test]
+!test_random_motion_waits_while_the_cylinder_stays_in_sight
    <- .system_time(T); -+homing(T); -+lastSighted(T);
       .system_time(T0); !move(0.5); .system_time(T1);
       !assert_true(homing(_));
       !assert_greater_than_equals(T1 - T0, 300).

@[test]
+!test_a_cylinder_lost_from_sight_is_ignored_a_while
    <- .system_time(T); -+homing(T - 5000); -+lastSighted(T - 5000); -+lostSightIgnore(1500);
       !move(0.5);
       !assert_false(homing(_));
       !until(ignoring, 1000);
       !assert_true(ignoring);
       !until(not ignoring, 6000);
       !assert_false(ignoring).

// an agent that believes homingProgress goes on past homingGiveUp while its cylinder still comes
// nearer, and gives up once no nearer sighting came for that long
@[test]
+!test_a_homing_still_coming_nearer_is_not_given_up
    <- !until(not ignoring, 3000); !forget_calls; -escaped; .system_time(T); -+homing(T - 60000);  // a minute
       +homingProgress(1000);
       !sighting(0, 0.38); .wait(100); !sighting(0, 0.3);          // nearer than before
       .wait(200);
       !assert_false(escaped);
       !assert_true(homing(_));
       .wait(1200); !sighting(0, 0.3);                              // no nearer sighting for 1.2 s
       !until(escaped, 2000);
       !assert_true(escaped);
       !assert_false(homing(_));
       -homingProgress(1000).
