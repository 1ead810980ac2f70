// Skill test of a cylinder knocked out by the storage area (skills/knock-fetch.asl, which knocked-aside.asl
// includes, with delivery.asl): a fall within the storage clearance and knockFetchWithin counts as by the area; for
// knockFetch ms after it (fellNearStorageAt, noted by delivery's fall plan) a cylinder may be picked
// near the storage point, where delivery otherwise allows none. The operations are mocked.
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/delivery.asl") }
{ include("../../main/asl/skills/knocked-aside.asl") }
{ include("../../main/asl/skills/search-memory.asl") }
{ include("../../main/asl/skills/gripper.asl") }   // its gripPoint (picking includes it)

maxSpeed(100).
storagePoint(0.4, -0.4).    // the world's, as the launcher gives them
storageRadius(0.1).         // so the storage clearance is 0.19 m, and a fall counts within 0.27 m
location(0, 0, 0).
mock_operation(_, ok).

@[test]
+!test_a_fall_by_the_storage_area_counts_and_one_far_from_it_does_not
    <- -+location(0.4, 0, -0.15);    // 0.25 m from the storage point
       !assert_true(fallenNearStorage);
       -+location(0.4, 0, -0.1);     // 0.3 m
       !assert_false(fallenNearStorage);
       -+location(0.1, 0, -0.4);
       !assert_false(fallenNearStorage).

@[test]
+!test_picking_near_the_storage_point_is_allowed_only_just_after_such_a_fall
    <- -+location(0.4, 0, -0.3);     // 0.1 m from the storage point: no pick as a rule
       -fellNearStorageAt(_);
       !assert_true(pickingOff);
       .system_time(T); +fellNearStorageAt(T);
       !assert_true(fetchingKnocked);
       !assert_false(pickingOff);
       // carrying it: no other pick
       +delivering; !assert_true(pickingOff); -delivering;
       // the time is out
       -+knockFetch(50); .wait(100);
       !assert_true(pickingOff);
       -+knockFetch(20000); -fellNearStorageAt(_).

@[test]
+!test_the_fetch_takes_nothing_from_the_pile
    <- -+location(0.4, 0, -0.3);     // 0.1 m from the storage point, just after a fall by the area
       .system_time(T); +fellNearStorageAt(T);
       -+orientation(270);           // facing the point: the gripper's point 0.05 m from it
       -+stored(0); !assert_false(pileAhead);   // no pile yet
       -+stored(1); !assert_true(pileAhead);
       !assert_true(pickingOff);
       -+orientation(90);            // facing away: the gripper's point 0.15 m from it
       !assert_false(pileAhead);
       !assert_false(pickingOff);
       -orientation(_); -stored(_); -fellNearStorageAt(_).
