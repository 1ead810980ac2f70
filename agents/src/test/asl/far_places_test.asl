// Skill test of far places (skills/far-places.asl, a try): a place remembered from farther than
// farSighting is forgotten at a delivery, a near one stays.
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/far-places.asl") }

location(0, 0, 0).
stored(0).

@[test]
+!test_a_far_sighting_is_forgotten_at_a_delivery_a_near_one_kept
    <- +seenCylinder(1.4, 0); +seenCylinder(0.5, 0.2); .wait(100);
       -+stored(1); .wait(100);
       !assert_false(seenCylinder(1.4, 0));
       !assert_true(seenCylinder(0.5, 0.2)).
