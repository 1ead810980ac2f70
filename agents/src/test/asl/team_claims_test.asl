// Skill tests of the team's claims (skills/team-claims.asl, in team-delivery.asl): a cylinder
// sighted is claimed on the task board at its estimated place, give or take an error that grows
// with its distance, swept on along the sighting's bearing beyond it, before the robot homes on it; one whose disc overlaps another robot's claim
// is left alone only while that claim stands; one near a teammate is left alone; a cylinder
// picked up is taken on the board, and put down where it is let go; a claim is released once. Artifact operations are mocked (see
// agents/README.md "Testing skills"). Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(1.0, 1.0).
storagePoint(0.41, -0.41).
storageRadius(0.1).
charger(-0.38, 0.38).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(claimAlong(_, _, _, _, _, 3), ok).
mock_operation(take(_, _, 7), ok).
mock_operation(putDown(_, _), ok).
mock_operation(_, ok).

@[test]
+!test_a_sighted_cylinder_is_claimed_at_its_estimated_place_then_homed_on
    <- +location(0.1, 0, 0.2); +orientation(90);
       !!perceive(cylinderSighted(0, 0.5));              // straight ahead, half a metre away
       !until(homing(_), 5000);
       ?mock_called(claimAlong(X, Z, R, Fx, Fz, 3));
       !assert_true(X > 0.09 & X < 0.11 & Z > 0.69 & Z < 0.71);
       !assert_true(R > 0.22 & R < 0.24);                 // 0.08 m + 0.3 m per metre of distance
       !assert_true(Fx > 0.09 & Fx < 0.11 & Fz > 1.15 & Fz < 1.17);   // swept on along the bearing: 2 R beyond
       !assert_true(myClaim(3)).

@[test]
+!test_a_cylinder_claimed_by_another_robot_is_left_alone_while_claimed
    <- -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _);
       +claimed(5, khepera2, 0.12, 0.75, 0.1);           // near the place of a sighting straight ahead
       !!perceive(cylinderSighted(0, 0.5));
       .wait(300);
       !assert_false(mock_called(claimAlong(_, _, _, _, _, _)));    // not even asked for
       !assert_false(homing(_));
       -claimed(5, khepera2, 0.12, 0.75, 0.1);           // khepera2 released it
       -cylinderSighted(_, _); !!perceive(cylinderSighted(0, 0.5));
       !until(homing(_), 5000);
       !assert_true(mock_called(claimAlong(_, _, _, _, _, 3))).    // anyone's again

@[test]
+!test_a_far_sighting_overlaps_a_claim_a_near_one_does_not
    <- -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _);
       +claimed(8, khepera3, 0.5, 1.3, 0.1);             // 0.4 m beside the far sighting's place
       !!perceive(cylinderSighted(0, 1.1));              // at (0.1, 1.3), give or take 0.41 m
       .wait(300);
       !assert_false(mock_called(claimAlong(_, _, _, _, _, _)));    // may be khepera3's cylinder: left alone
       -claimed(8, khepera3, 0.5, 1.3, 0.1);
       +claimed(8, khepera3, 0.5, 0.6, 0.1);             // 0.4 m beside a near sighting's place
       -cylinderSighted(_, _); !!perceive(cylinderSighted(0, 0.4));   // at (0.1, 0.6), give or take 0.2 m
       !until(homing(_), 5000);
       !assert_true(mock_called(claimAlong(_, _, _, _, _, 3)));    // another cylinder: claimed
       -claimed(8, khepera3, 0.5, 0.6, 0.1).

@[test]
+!test_the_board_refusing_a_claim_stops_the_homing
    <- -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _);
       +mock_operation(claimAlong(_, _, _, _, _, _), fail("khepera3 has claimed it", claimed_by(khepera3, 6)));
       .abolish(mock_operation(claimAlong(_, _, _, _, _, 3), ok));
       !!perceive(cylinderSighted(-10, 0.8));
       !until(claimRefused, 5000);
       !assert_true(claimRefused);
       !assert_false(homing(_));
       !assert_false(myClaim(_));
       .abolish(mock_operation(claimAlong(_, _, _, _, _, _), _)); +mock_operation(claimAlong(_, _, _, _, _, 3), ok).

@[test]
+!test_a_cylinder_next_to_a_teammate_is_left_alone
    <- -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _);
       +robotAt(khepera4, 0.1, 0.65);                      // 5 cm from the sighting's place: it carries it
       !!perceive(cylinderSighted(0, 0.5));
       .wait(300);
       !assert_false(mock_called(claimAlong(_, _, _, _, _, _)));
       !assert_false(homing(_));
       -robotAt(khepera4, 0.1, 0.65).

@[test]
+!test_a_picked_cylinder_is_taken_on_the_board
    <- -homing(_); !forget_calls; +myClaim(3);
       -picked(false); !!perceive(picked(true));
       !until(myClaim(7), 5000);
       ?mock_called(take(X, Z, 7));
       !assert_true(X > 0.09 & X < 0.11 & Z > 0.24 & Z < 0.26);  // in the gripper, 5 cm ahead
       !assert_false(myClaim(3)).

@[test]
+!test_a_cylinder_let_go_is_put_down_on_the_board_where_it_is
    <- !forget_calls; +myClaim(7); +picked(true);       // at (0.1, 0.2), heading 90: carrying
       !!unperceive(picked(true));
       !until(mock_called(putDown(_, _)), 5000);
       ?mock_called(putDown(X, Z));
       !assert_true(X > 0.09 & X < 0.11 & Z > 0.24 & Z < 0.26).   // where the gripper held it, 5 cm ahead

@[test]
+!test_a_claim_the_board_voided_does_not_fail_the_next_claim
    <- -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _); -+picked(false);
       +myClaim(14);                                          // voided meanwhile: the board has no claim 14
       +mock_operation(release(14), fail("no claim 14 on the task board", no_claim(14)));
       !!perceive(cylinderSighted(0, 0.5));
       !until(homing(_), 5000);
       !assert_true(homing(_));                                // the new claim stands, the homing goes on
       !assert_true(myClaim(3));
       !assert_false(myClaim(14)).

@[test]
+!test_a_sighting_in_the_line_of_a_teammate_that_carries_is_left_alone
    <- -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _); -+picked(false);
       // khepera3 carries (its claim sits on its place) 1 m straight ahead; the sighting is
       // estimated 0.3 m ahead, 0.7 m short of it: its distance is the rough part
       +robotAt(khepera3, 0.1, 1.2); +claimed(9, khepera3, 0.1, 1.2, 0.2);
       !!perceive(cylinderSighted(2, 0.3));
       .wait(300);
       !assert_false(mock_called(claimAlong(_, _, _, _, _, _)));
       !assert_false(homing(_));
       -claimed(9, khepera3, 0.1, 1.2, 0.2);                   // it has put its cylinder down: a teammate
       -cylinderSighted(_, _); !!perceive(cylinderSighted(2, 0.3));   // that carries nothing hides nothing
       !until(homing(_), 5000);
       !assert_true(mock_called(claimAlong(_, _, _, _, _, 3)));
       -robotAt(khepera3, 0.1, 1.2).

@[test]
+!test_a_sighting_in_the_line_of_the_stored_pile_is_left_alone
    <- -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _); -+picked(false);
       -+orientation(297);                                     // facing the storage point, 0.68 m away: a sighting
       !!perceive(cylinderSighted(0, 0.3));                    // straight ahead is in its line
       !until(homing(_), 5000);
       !assert_true(mock_called(claimAlong(_, _, _, _, _, 3)));           // nothing stored yet: a cylinder there is one
       -homing(_); -myClaim(_); !forget_calls; -cylinderSighted(_, _);
       -+completed(1);                                         // the team has stored one: it may be the pile
       !!perceive(cylinderSighted(0, 0.3));
       .wait(300);
       !assert_false(mock_called(claimAlong(_, _, _, _, _, _)));
       !assert_false(homing(_));
       -cylinderSighted(_, _); !!perceive(cylinderSighted(25, 0.3));  // another bearing: claimed
       !until(homing(_), 5000);
       !assert_true(mock_called(claimAlong(_, _, _, _, _, 3)));
       -completed(1); -+orientation(90).

// the homing given up (-homing) and the trip to the charger begun (+charging) in one step both
// release the claim: the board is asked once (the second release failed, inside the trip's atomic start)
@[test]
+!test_a_claim_is_released_once
    <- -homing(_); -myClaim(_); !forget_calls; -+picked(false);
       +mock_operation(release(3, _), ok);   // (an earlier test's abolish of claimAlong's mocks took the catch-all)
       +myClaim(3);
       !releaseClaim(3, test);
       !until(mock_called(release(3, _)), 1000);
       !assert_true(mock_called(release(3, _)));
       !forget_calls;
       !releaseClaim(3, test); .wait(100);
       !assert_false(mock_called(release(_, _)));
       !assert_false(myClaim(3)).

// with a teammate, the cylinder is taken once the gripper holds it, before it is picked up; let go
// before that, its claim is put down where it is; alone, only the pick takes it
@[test]
+!test_with_a_teammate_a_caught_cylinder_is_taken_before_it_is_picked
    <- -homing(_); -myClaim(_); -+picked(false); !forget_calls;   // at (0.1, 0.2), heading 90
       +picking; !!perceive(caught(true));
       .wait(300);
       !assert_false(mock_called(take(_, _, _)));               // alone: not yet
       -caught(true); +robotAt(khepera4, -0.3, -0.3); !forget_calls;
       !!perceive(caught(true));
       !until(myClaim(7), 5000);
       ?mock_called(take(X, Z, 7));
       !assert_true(X > 0.09 & X < 0.11 & Z > 0.24 & Z < 0.26);  // in the gripper, 5 cm ahead
       -caught(true); !!perceive(caught(false));
       !until(mock_called(putDown(_, _)), 5000);
       !assert_false(takenCaught);
       -picking; -caught(false); -myClaim(_); -robotAt(khepera4, _, _).

// with a teammate, a claim whose cylinder was lost from sight is kept while the robot drives back to
// its place to look again; the search moving on (its next waypoint) releases it
@[test]
+!test_with_a_teammate_a_claim_lost_from_sight_is_sought_again_then_released
    <- -homing(_); -myClaim(_); -+picked(false); !forget_calls; .my_name(Me);
       +robotAt(khepera4, -0.3, -0.3); +searching; +mock_operation(release(3, _), ok);
       +mock_operation(searchFrom(_, _, 0.3, -0.2), ok);
       +myClaim(3); +claimed(3, Me, 0.1, 0.7, 0.1);
       .system_time(T); -+lastSighted(T - 3000); +homing(T - 5000);
       -homing(_);                                               // lost from sight 3 s ago
       !until(seekingClaim(3, _, _, _), 5000);
       !assert_true(waypoint(0.1, 0.7, _));                      // back to the claim's place
       !assert_true(myClaim(3));
       !assert_false(mock_called(release(_, _)));
       !nextWaypoint;                                            // reached, skipped or escaped
       !assert_true(mock_called(release(3, notFoundAgain)));     // the board logs the reason
       !assert_false(myClaim(3));
       !assert_false(seekingClaim(_, _, _, _));
       !assert_true(waypoint(0.3, -0.2, _));                     // on with the team's search
       -searching; -claimed(3, Me, _, _, _); -robotAt(khepera4, _, _); .abolish(waypoint(_, _, _)).

// with a teammate, a red side of the image is not reached for while homing (far sight steers to its
// cylinder) nor in the line of the stored pile; alone, picking's reach turns to it
@[test]
+!test_with_a_teammate_a_lateral_cylinder_is_left_while_homing_or_in_the_piles_line
    <- -homing(_); -myClaim(_); -+picked(false); !forget_calls; -+reachCylinder(false);
       +robotAt(khepera4, -0.3, -0.3); .system_time(T); +homing(T);
       !!perceive(cylinderLeft); .wait(300);
       !assert_true(reachCylinder(false));
       -homing(_); -cylinderLeft;
       -+orientation(317); -+completed(1);                    // the storage point 20 degrees to the left
       !!perceive(cylinderLeft); .wait(300);
       !assert_true(reachCylinder(false));
       -cylinderLeft; -robotAt(khepera4, _, _);                // alone: reached for
       !!perceive(cylinderLeft);
       !until(reachCylinder(true), 5000);
       !assert_true(reachCylinder(true));
       !until(reachCylinder(false), 8000);                     // no cylinder comes ahead: the reach fails
       -cylinderLeft; -completed(1); -+orientation(90).
