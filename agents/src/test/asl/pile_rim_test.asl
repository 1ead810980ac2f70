// Skill test of the look at the storage area's rim (skills/pile-rim.asl): once the sweep has gone
// through all its waypoints since the search began and a cylinder is still to store, the next
// waypoints are points round the storage point, towards the arena's centre first; at each the robot
// drives straight at the storage point until it is just short of the storage clearance, no lateral
// reach by the pile meanwhile. Not with every cylinder stored. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/pile-rim.asl") }
{ include("../../main/asl/skills/sweep.asl") }

maxSpeed(100).
arena(2, 2).                 // the world's, as the launcher gives them
storagePoint(0.75, 0.75).
cylinders(2).
storageClearance(0.15).      // delivery's, and its rule
storageWithin(E) :- location(X, _, Z) & storagePoint(Sx, Sz) & storageClearance(C)
    & (X - Sx) * (X - Sx) + (Z - Sz) * (Z - Sz) < (C + E) * (C + E).
location(0, 0, 0).

mock_operation(computeAngle(_, _, _, _, 45), ok).
mock_operation(_, ok).

+!balance <- +balanced.
+!aimAt(X, Z) <- -+aim(X, Z).
+!escape.

// the sweep's seven waypoints, planSweep took the first: five more leave one not yet taken, the
// next two bring the list's head back where the lanes began
+!lanes_nearly_gone_through <- for (.range(_, 1, 5)) { !nextWaypoint; .wait(20) }.
+!lanes_come_round <- for (.range(_, 1, 2)) { if (not rimPoints(_)) { !nextWaypoint; .wait(50) } }.
+!search_anew <- -searching; .wait(50); .abolish(sweep(_)); .abolish(waypoint(_, _, _)); +searching; !planSweep; .wait(50).

@[test]
+!test_the_lanes_gone_through_with_a_cylinder_left_lead_to_the_storage_areas_rim
    <- -+stored(1); !search_anew;
       !lanes_nearly_gone_through; .wait(100);
       !assert_false(rimPoints(_));                         // not before
       !lanes_come_round;
       !until(rimPoints(_), 1000);
       !nextWaypoint;
       ?waypoint(X, Z, _);                                  // 0.35 m from the storage point, towards the centre
       !assert_equals(0.5025, X, 0.001); !assert_equals(0.5025, Z, 0.001);
       !nextWaypoint; ?waypoint(X2, Z2, _);                 // then 45 degrees to one side
       !assert_equals(0.40, X2, 0.001); !assert_equals(0.75, Z2, 0.001);
       !nextWaypoint; ?waypoint(X3, Z3, _);                 // and to the other
       !assert_equals(0.75, X3, 0.001); !assert_equals(0.40, Z3, 0.001);
       !nextWaypoint; ?waypoint(X4, _, _);                  // then the lanes again (their ends at x = -0.75, 0.75)
       !assert_equals(0.75, math.abs(X4), 0.001);
       !assert_false(rimStart(_, _)).

@[test]
+!test_with_every_cylinder_stored_the_lanes_go_on
    <- -+stored(2); !search_anew;
       !lanes_nearly_gone_through; !lanes_come_round;
       .wait(100);
       !nextWaypoint;
       !assert_false(rimPoints(_));
       !assert_false(waypoint(0.5025, 0.5025, _)).

@[test]
+!test_at_a_rim_start_the_robot_drives_at_the_storage_point_until_short_of_its_clearance
    <- !forget_calls; -+stored(1); +searching; -+rimPoints([[0.40, 0.75]]); -+rimStart(0.5025, 0.5025);
       -+waypoint(0.5025, 0.5025, 0); -+location(0.5, 0, 0.5);
       !!sweepStep;
       !until(mock_called(setSpeeds(50, 50)), 1000);
       !assert_true(mock_called(computeAngle(0.5, 0.5, 0.75, 0.75, 45)));
       !assert_true(desired(45) & balanced);
       !assert_true(mock_called(setSpeeds(50, 50)));        // straight on at half speed
       .wait(300);
       !assert_true(rimStart(0.5025, 0.5025));              // still on its way
       -+location(0.64, 0, 0.64);                           // 0.156 m from the storage point: within 1 cm of 0.15
       !until(rimStart(0.40, 0.75), 1000);
       !assert_true(mock_called(stop));
       !assert_true(waypoint(0.40, 0.75, _));               // on to the next start
       -+location(0, 0, 0); -searching.

// no lateral reach during the look within 0.1 m of the storage clearance (the pile's cylinders)
@[test]
+!test_no_lateral_reach_by_the_pile_during_the_look
    <- -+rimStart(0.5025, 0.5025); -+location(0.6, 0, 0.6);         // 0.21 m from the storage point
       !assert_true(reachOff);
       -+location(0.5, 0, 0.5);                                       // 0.35 m
       !assert_false(reachOff);
       -rimStart(0.5025, 0.5025); -+location(0.6, 0, 0.6);
       !assert_false(reachOff);
       -+location(0, 0, 0).
