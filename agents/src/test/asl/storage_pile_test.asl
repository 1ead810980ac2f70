// Skill test of a cylinder knocked out by the pile (skills/knocked-aside.asl with delivery.asl, tidy-up's):
// a fall with the gripper's point within the storage clearance notes lostByPile(T) (delivery's fall plan); not
// picked again within knockCounted ms, the cylinder counts with the stored ones (storedOrByPile: tidy-up's end
// condition); a pick before the count, or by the storage area after it, was of that cylinder (fetchedByPile:
// delivery's pick plan forgets it). The operations are mocked.
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/delivery.asl") }
{ include("../../main/asl/skills/knocked-aside.asl") }
{ include("../../main/asl/skills/search-memory.asl") }   // its gripReach, gripPoint

maxSpeed(100).
storagePoint(0.4, -0.4).    // the world's, as the launcher gives them
storageRadius(0.1).         // so the storage clearance is 0.19 m
location(0, 0, 0).
mock_operation(_, ok).

@[test]
+!test_a_cylinder_knocked_out_by_the_pile_and_not_picked_again_counts_as_stored
    <- -+location(0.4, 0, -0.3); -+orientation(270);   // the gripper's point 0.05 m from the storage point
       !assert_true(fallenByPile);
       -+orientation(90);            // 0.15 m, within the storage clearance (0.19 m)
       !assert_true(fallenByPile);
       -+location(0.4, 0, -0.1);     // 0.35 m
       !assert_false(fallenByPile);
       -+stored(1); -knockCounted(_); .system_time(T); +lostByPile(T);   // not counted yet
       !assert_true(storedOrByPile(1));
       !assert_true(fetchedByPile);  // a pick before the count is of that cylinder
       -lostByPile(_); -+knockCounted(100); .system_time(T2); +lostByPile(T2);
       !until(countedByPile, 3000);
       !assert_true(storedOrByPile(2));
       !assert_false(fetchedByPile); // counted: a pick far from the storage area is another cylinder
       -+location(0.4, 0, -0.2);     // 0.2 m from the storage point: one picked there is that one
       !assert_true(fetchedByPile);
       -lostByPile(_); -+knockCounted(30000); -orientation(_); -stored(_); -+location(0, 0, 0).
