// Skill test of the way round the storage area (skills/storage-bypass.asl): while the straight way
// to the sweep's waypoint passes within laneClearance of the storage point, the robot heads for the
// point beside the area on the side the way passes; a clear way, a trip (travelling) and a target
// that is not the sweep's waypoint head straight. The operations are mocked (agents/README.md
// "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/storage-bypass.asl") }

arena(3, 2).                 // the world's, as the launcher gives them
storagePoint(0, 0).
laneClearance(0.25).         // sweep's
location(-1, 0, 0.1).
searching.
travelling :- delivering.

mock_operation(_, ok).

// heading's: the straight way
+!aimAt(X, Z) <- -+aim(X, Z).

@[test]
+!test_a_lane_across_the_storage_area_heads_beside_it_on_its_side
    <- -+location(-1, 0, 0.1); -+waypoint(1, 0.1, 0);
       !aimAt(1, 0.1);
       ?aim(Ax, Az); !assert_equals(Ax, 0, 0.001); !assert_equals(Az, 0.3, 0.001).

@[test]
+!test_a_lane_through_the_storage_point_heads_beside_it_towards_the_centre
    <- -+storagePoint(0, -0.5); -+location(-1, 0, -0.5); -+waypoint(1, -0.5, 0);
       !aimAt(1, -0.5);
       ?aim(Ax, Az); !assert_equals(Ax, 0, 0.001); !assert_equals(Az, -0.2, 0.001);
       -+storagePoint(0, 0).

@[test]
+!test_past_the_storage_area_the_way_is_clear
    <- -+location(0, 0, 0.3); -+waypoint(1, 0.1, 0);
       !aimAt(1, 0.1);
       !assert_true(aim(1, 0.1));
       -+location(-1, 0, 0.1).

@[test]
+!test_a_trip_and_another_target_head_straight
    <- -+location(-1, 0, 0.1); -+waypoint(1, 0.1, 0);
       +delivering; !aimAt(1, 0.1); -delivering;
       !assert_true(aim(1, 0.1));
       !aimAt(1, -0.1);
       !assert_true(aim(1, -0.1)).
