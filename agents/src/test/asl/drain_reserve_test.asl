// Skill tests of the charge reserve after a drain (skills/drain-reserve.asl, tidy-up's): a charge
// ends with chargeReserve J over the time left's need until the battery falls by more than drainStep
// between two readings, with drainReserve J after that; a fall the wheels can make, or a rise on the
// charger, is no drain. The battery percept is added and removed as beliefs.
// Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/drain-reserve.asl") }

@[test]
+!test_a_fall_the_wheels_make_or_a_charge_keeps_the_reserve
    <- -drainSeen; -+battery(900);
       -+battery(899.9); -+battery(880); -+battery(950);
       .wait(200);
       !assert_false(drainSeen);
       !assert_true(chargeUntilLasts(100)).

@[test]
+!test_a_drain_raises_the_reserve_for_the_rest_of_the_run
    <- -drainSeen; -+battery(700);
       -+battery(520);                       // 180 J between two readings
       !until(drainSeen, 2000);
       !assert_true(drainSeen);
       !assert_true(chargeUntilLasts(300));
       !assert_false(chargeUntilLasts(100));
       -+battery(999);                       // charged again: the reserve stays
       .wait(200);
       !assert_true(chargeUntilLasts(300));
       -drainSeen.
