// Test of navigation's agent as composed (navigation.asl, its skills read in): a cylinder seen while
// another is carried is remembered for the search after the delivery (search-memory.asl), and the
// sweep's way to a waypoint across the storage area heads beside the area (storage-bypass.asl). The
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
