// Skill test of the search memory (skills/search-memory.asl): a cylinder seen and not gone for is
// remembered where the sighting puts it, once however often it is seen, never in the storage
// area; picking it forgets it; a search goes first to the nearest one remembered, else on along
// the sweep's lanes. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/search-memory.asl") }
{ include("../../main/asl/skills/gripper.asl") }   // its gripPoint (picking includes it)

location(0, 0, 0).
orientation(0).
arena(3, 3).
storagePoint(-1, -1).
storageClearance(0.15).

mock_operation(_, ok).

maxSpeed(100).

// what the skill needs of sweep
+!planSweep <- +sweepPlanned; -+sweep([[0.5, 0.5]]).
+!lookAround <- +lookedAround.
+!sweepStep.
+!nextWaypoint <- .abolish(waypoint(_, _, _)); +waypoint(0.5, 0.5, 0).

@[test]
+!test_a_sighting_is_remembered_where_it_puts_the_cylinder_once
    <- .abolish(seenCylinder(_, _));
       +cylinderSighted(0, 1);                          // 1 m straight ahead (heading 0: +x)
       !until(seenCylinder(_, _), 500);
       ?seenCylinder(X, Z); !assert_equals(X, 1, 0.001); !assert_equals(Z, 0, 0.001);
       -cylinderSighted(0, 1); +cylinderSighted(5, 1.05);  // the same one, seen again a little aside
       .wait(100);
       .count(seenCylinder(_, _), N); !assert_true(N == 1);
       -cylinderSighted(5, 1.05); +cylinderSighted(90, 0.5);  // another: 0.5 m to the right (+z)
       !until(seenCylinder(_, 0.5), 500);
       ?seenCylinder(X2, Z2); !assert_equals(X2, 0, 0.001); !assert_equals(Z2, 0.5, 0.001);
       -cylinderSighted(90, 0.5).

@[test]
+!test_a_cylinder_in_the_storage_area_is_not_remembered
    <- .abolish(seenCylinder(_, _)); -+location(-1, 0, -1.5);
       +cylinderSighted(90, 0.5);                       // at the storage point: a stored one
       .wait(100);
       !assert_false(seenCylinder(_, _));
       -cylinderSighted(90, 0.5); -+location(0, 0, 0).

@[test]
+!test_a_sighting_beyond_a_wall_is_put_at_the_wall
    <- .abolish(seenCylinder(_, _)); -+location(1, 0, 0);
       +cylinderSighted(0, 1.5);                        // 1.5 m ahead: 1 m beyond the wall at x = 1.5
       !until(seenCylinder(_, _), 500);
       ?seenCylinder(X, Z); !assert_equals(X, 1.45, 0.001); !assert_equals(Z, 0, 0.001);
       -cylinderSighted(0, 1.5); -+location(0, 0, 0).

@[test]
+!test_a_sighting_through_the_storage_area_after_a_delivery_is_not_remembered
    <- .abolish(seenCylinder(_, _)); -+location(-1, 0, 0); -+orientation(270); +stored(1);
       +cylinderSighted(0, 1.5);                        // towards the storage point 1 m away, seen 1.5 m off
       .wait(100);
       !assert_false(seenCylinder(_, _));
       -cylinderSighted(0, 1.5); -stored(1);
       +cylinderSighted(0, 0.5);                        // nothing stored yet: a cylinder on the way
       !until(seenCylinder(_, _), 500);
       !assert_true(seenCylinder(_, _));
       -cylinderSighted(0, 0.5); -+location(0, 0, 0); -+orientation(0).

// the stored pile's cylinders side by side seem one wide cylinder, nearer than it is: a sighting
// towards the storage point 2 m ahead, put at 0.6 m, is the pile; one put at 0.4 m is a cylinder
@[test]
+!test_the_stored_pile_seen_as_one_near_cylinder_is_not_remembered
    <- .abolish(seenCylinder(_, _)); -+location(-1, 0, 1); -+orientation(270); +stored(3);
       +cylinderSighted(0, 0.6);
       .wait(100);
       !assert_false(seenCylinder(_, _));
       -cylinderSighted(0, 0.6); +cylinderSighted(0, 0.4);
       !until(seenCylinder(_, _), 500);
       !assert_true(seenCylinder(_, _));
       -cylinderSighted(0, 0.4); -stored(3); .abolish(seenCylinder(_, _)); -+location(0, 0, 0); -+orientation(0).

// far sight goes for no sighting of the stored pile either (its rule sightingOff)
@[test]
+!test_far_sight_goes_for_no_sighting_of_the_stored_pile
    <- -+location(-1, 0, 1); -+orientation(270); +stored(3);
       !assert_true(sightingOff(0, 0.6));               // the pile, seen nearer than it is
       !assert_false(sightingOff(0, 0.4));              // a cylinder before it
       !assert_false(sightingOff(90, 0.6));             // away from the storage area
       -stored(3); !assert_false(sightingOff(0, 0.6));  // nothing stored: a cylinder
       -+location(0, 0, 0); -+orientation(0).

@[test]
+!test_picking_a_cylinder_forgets_it
    <- .abolish(seenCylinder(_, _)); +seenCylinder(0.1, 0); +seenCylinder(1, 1);
       +picked(true);
       !until(not seenCylinder(0.1, 0), 500);
       !assert_false(seenCylinder(0.1, 0));
       !assert_true(seenCylinder(1, 1));                // another place: kept
       -picked(true).

// the places forgotten are those near the cylinder in the gripper (gripReach 0.05 m ahead), not near
// the robot's centre: one 0.24 m beyond the cylinder goes, one 0.22 m behind the robot stays
@[test]
+!test_picking_forgets_the_places_near_the_cylinder_in_the_gripper
    <- .abolish(seenCylinder(_, _)); -+location(0, 0, 0); -+orientation(90);   // heading +z
       !assert_true(gripReach(0.05));
       +seenCylinder(0, 0.29); +seenCylinder(0, -0.22);
       +picked(true);
       !until(not seenCylinder(0, 0.29), 500);
       !assert_false(seenCylinder(0, 0.29));
       !assert_true(seenCylinder(0, -0.22));
       -picked(true); -+orientation(0).

// without a compass the cylinder's place is unknown: the places near the robot's centre go
@[test]
+!test_picking_without_a_compass_forgets_the_places_near_the_robot
    <- .abolish(seenCylinder(_, _)); -+location(0, 0, 0); -orientation(_);
       +seenCylinder(0.2, 0); +seenCylinder(0, 0.3);
       +picked(true);
       !until(not seenCylinder(0.2, 0), 500);
       !assert_false(seenCylinder(0.2, 0));
       !assert_true(seenCylinder(0, 0.3));
       -picked(true); +orientation(0).

@[test]
+!test_a_search_goes_first_to_the_nearest_cylinder_remembered
    <- .abolish(seenCylinder(_, _)); -searching; -sweep(_); -sweepPlanned;
       +seenCylinder(1, 1); +seenCylinder(0.3, -0.2);
       !searchFromMemory;
       !assert_true(searching & waypoint(0.3, -0.2, _));
       !assert_false(seenCylinder(0.3, -0.2));          // one visit: not looked for again
       !assert_true(seenCylinder(1, 1) & sweepPlanned).  // the lanes come after it

// the sweep's lanes begin at the arena's corner nearest the robot (sweep.asl reads sweepFrom)
@[test]
+!test_the_sweep_begins_at_the_corner_nearest_the_robot
    <- -+location(0.4, 0, -1.2); ?sweepFrom(Fx, Fz);
       !assert_true(Fx == -1 & Fz == 1);
       -+location(-0.4, 0, 1.2); ?sweepFrom(Fx2, Fz2);
       !assert_true(Fx2 == 1 & Fz2 == -1);
       -+location(0, 0, 0).

// a look again with nothing left remembered (another intention took the last place first) ends
// quietly and leaves the waypoint as it was: its failure ended the robot's motion loop
@[test]
+!test_looking_again_with_nothing_remembered_keeps_the_waypoint
    <- .abolish(seenCylinder(_, _)); .abolish(waypoint(_, _, _)); +waypoint(0.5, 0.5, 0);
       !lookAgain;
       !assert_true(waypoint(0.5, 0.5, 0)).

@[test]
+!test_with_nothing_remembered_a_search_goes_on_along_the_lanes
    <- .abolish(seenCylinder(_, _)); -searching; -sweepPlanned;
       !searchFromMemory;
       !assert_true(searching & sweepPlanned).

@[test]
+!test_the_sweep_goes_to_the_nearest_cylinder_remembered_before_its_next_lane
    <- .abolish(seenCylinder(_, _)); +searching; -+sweep([[0.5, 0.5]]);
       +seenCylinder(-1, 1); +seenCylinder(0.2, 0.4);
       !nextWaypoint;
       !assert_true(waypoint(0.2, 0.4, _));
       !assert_false(seenCylinder(0.2, 0.4));
       !assert_true(sweep([[0.5, 0.5]]));               // the lanes wait
       -searching.

// a cylinder knocked out of the gripper lies beside the robot: the look around after the fall
// starts a little back from it, with sightings on; after a delivery there is no backing off
@[test]
+!test_after_a_cylinder_lost_on_the_way_the_look_around_starts_backed_off_with_sightings_on
    <- !forget_calls; -lookedAround; +ignoring;
       +delivering; -delivering;                        // the delivery ended outside the storage area
       !until(lostBeside, 500);
       +lookFirst; !move(0.5);
       !assert_true(mock_called(setSpeeds(-50, -50)));
       !assert_true(lookedAround);
       !assert_false(ignoring);
       !assert_false(lostBeside);
       !forget_calls; -lookedAround; +insideArea; +delivering; -delivering;   // delivered
       .wait(100);
       !assert_false(lostBeside);
       -insideArea.

// an avoidance during the back-off after a fall ends the move (the box a wall following was along):
// with fallLookKept the look around is not lost with it, it comes at the next move, and once only
@[test]
+!test_a_back_off_cut_short_by_an_avoidance_still_gives_the_look_around_at_the_next_move
    <- !forget_calls; -lookedAround; +ignoring; +fallLookKept;
       +delivering; -delivering;                        // the cylinder fell on the way
       !until(lostBeside, 500);
       +lookFirst; !!move(0.5);
       !until(mock_called(setSpeeds(-50, -50)), 500);
       .succeed_goal(move(_));                          // the avoidance's
       !assert_false(lookedAround);
       !move(0.5);                                      // the move after the avoidance
       !assert_true(lookedAround);
       !assert_false(ignoring);
       !assert_false(lookFirst);
       !assert_false(backingOff);
       -fallLookKept.

// a place looked for again, straight ahead and near, with no sighting for 2 s: nothing is there, and
// the search goes on to the next place (the sweep's waypoint, here) instead of driving to it
@[test]
+!test_a_remembered_place_in_view_and_empty_is_left_for_the_next
    <- .abolish(seenCylinder(_, _)); .abolish(lookingAgain(_, _, _)); -+location(0, 0, 0); -+orientation(0);
       +seenCylinder(0.6, 0.1);                         // 0.61 m ahead, 9.5 degrees to the right
       +searching; !lookAgain;
       !assert_true(waypoint(0.6, 0.1, _));
       !sweepStep;                                       // in view: from now on
       !assert_true(lookingAgain(0.6, 0.1, _));
       !assert_true(waypoint(0.6, 0.1, _));
       .wait(2100); !sweepStep;                          // still in view, and no sighting took the robot away
       !assert_false(waypoint(0.6, 0.1, _));
       !assert_false(lookingAgain(_, _, _));
       -searching.

// the place looked for again out of view (behind the robot) is driven to as before
@[test]
+!test_a_remembered_place_out_of_view_is_still_driven_to
    <- .abolish(seenCylinder(_, _)); .abolish(lookingAgain(_, _, _)); -+location(0, 0, 0); -+orientation(180);
       +seenCylinder(0.6, 0.1); +searching; !lookAgain;
       !sweepStep; .wait(2100); !sweepStep;
       !assert_true(waypoint(0.6, 0.1, _));
       !assert_true(lookingAgain(0.6, 0.1, 0));
       -searching.

// a homing that lost sight of its cylinder remembers it where the last sighting put it, whatever
// the robot turned since, and a search goes there; a homing stale since the last pick does not
@[test]
+!test_a_cylinder_lost_from_sight_while_homing_is_remembered_where_last_seen
    <- .abolish(seenCylinder(_, _)); .abolish(lookingAgain(_, _, _)); -+location(0, 0, 0); -+orientation(90);
       -+lastFound(-300000); -+lastSighted(-100000); -+sightDistance(0.5);
       -+sightOffset(-90);                               // far sight's last sighting: 0.5 m to the left (+x)
       !until(lastSightedAt(_, _), 500);
       -+orientation(135);                               // the homing's turn went on past it
       +homing(-200000); -homing(_);                     // lost from sight (far sight's move plan)
       !until(seenCylinder(_, _), 500);
       ?seenCylinder(X, Z); !assert_equals(X, 0.5, 0.001); !assert_equals(Z, 0, 0.001);
       .abolish(seenCylinder(_, _));
       +homing(-400000); -homing(_); .wait(200);          // began before the last pick: stale
       !assert_false(seenCylinder(_, _));
       .abolish(lastFound(_)); .abolish(lastSighted(_)); .abolish(sightDistance(_)); .abolish(sightOffset(_));
       .abolish(lastSightedAt(_, _)); -+orientation(0).
