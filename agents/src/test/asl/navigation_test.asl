// Test of navigation's agent as composed (navigation.asl, its skills read in): a cylinder seen while
// another is carried is remembered for the search after the delivery (search-memory.asl), and the
// sweep's way to a waypoint across the storage area heads beside the area (storage-bypass.asl); a
// cylinder knocked out of the gripper by the storage area is turned to and may be picked there
// (knock-fetch.asl), a knock elsewhere is left to the search (no knocked-aside.asl). The
// operations are mocked; the robot never connects, so only the plans under test run
// (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/navigation.asl") }

arena(3, 2).                 // the world's, as the launcher gives them
storagePoint(0, 0).
storageRadius(0.06).
location(-1, 0, 0.1).
orientation(0).

mock_operation(_, ok).

@[test]
+!test_a_cylinder_seen_while_carrying_one_is_remembered
    <- .abolish(seenCylinder(_, _)); -+location(-1, 0, 0.1); +picked(true);
       +cylinderSighted(0, 0.5);                        // 0.5 m straight ahead (heading 0: +x)
       !until(seenCylinder(_, _), 1000);
       -cylinderSighted(0, 0.5); -picked(true);
       ?seenCylinder(X, Z); !assert_equals(X, -0.5, 0.001); !assert_equals(Z, 0.1, 0.001).

@[test]
+!test_the_sweep_heads_beside_the_storage_area_across_its_lane
    <- -+location(-1, 0, 0.1); +searching; -+waypoint(1, 0.1, 0);
       !aimAt(1, 0.1);                                  // laneClearance: 0.06 + 0.09 + 0.1 m
       -searching; .abolish(waypoint(_, _, _));
       ?aim(Ax, Az); !assert_equals(Ax, 0, 0.001); !assert_equals(Az, 0.3, 0.001).

@[test]
+!test_a_cylinder_knocked_out_by_the_storage_area_is_turned_to_and_may_be_picked
    <- -+location(0.1, 0, 0); -+maxSpeed(100); -+reachCylinder(false); !forget_calls;
       -fellNearStorageAt(_); -knockedAt(_);
       !assert_true(pickingOff);                        // 0.1 m from the storage point: no pick as a rule
       !assert_true(fallenNearStorage);                 // what delivery's fall plan tests
       .system_time(T); +fellNearStorageAt(T); +knockedAt(T);   // as that plan notes the fall
       !assert_false(pickingOff);
       -+delta(40); !!perceive(obstacle(true)); -obstacle(true);
       !until(mock_called(setSpeeds(-25, 25)), 1000);
       !assert_true(mock_called(setSpeeds(-25, 25)));   // towards the left, where it shows
       -+reachCylinder(true); !until(not avoiding, 1000);
       -+reachCylinder(false); -fellNearStorageAt(_).

@[test]
+!test_a_knock_away_from_the_storage_area_is_left_to_the_search
    <- -+location(-1, 0, 0.1); -knockedAt(_);
       !assert_false(fallenNearStorage);
       +lostBeside; .wait(50); -lostBeside;
       !assert_false(knockedAt(_)).
