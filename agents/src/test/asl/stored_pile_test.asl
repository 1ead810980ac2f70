// Skill test of the stored pile left alone (skills/stored-pile.asl): a lateral cylinder signal while
// the storage point lies near and ahead, something stored there, is no reach; one elsewhere, or
// before anything is stored, is picking's reach as before. The operations are mocked
// (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/stored-pile.asl") }
{ include("../../main/asl/skills/picking.asl") }

maxSpeed(100).
mock_operation(_, ok).
storagePoint(-1, -1).
orientation(0).                 // heading +x
location(-1.3, 0, -1).          // 0.3 m short of the storage point, facing it
stored(1).

+!go_ahead : picked(true) <- -picking.
+!escape.
+!move(_).

@[test]
+!test_a_lateral_cylinder_with_the_pile_ahead_is_no_reach
    <- !forget_calls; -+reachCylinder(false); -+stored(1); -+location(-1.3, 0, -1);
       !!perceive(cylinderLeft);
       .wait(300);
       !assert_false(mock_called(setSpeeds(0, 10)));
       !assert_true(reachCylinder(false));
       -cylinderLeft.

@[test]
+!test_a_lateral_cylinder_away_from_the_pile_is_reached
    <- !forget_calls; -+reachCylinder(false); -+stored(1); -+location(0.5, 0, -1);   // 1.5 m from it
       !!perceive(cylinderRight);
       !until(mock_called(setSpeeds(10, 0)), 2000);
       !assert_true(reachCylinder(true));
       -cylinderRight; -+reachCylinder(false).

@[test]
+!test_a_lateral_cylinder_before_anything_is_stored_is_reached
    <- !forget_calls; -+reachCylinder(false); -+stored(0); -+location(-1.3, 0, -1);
       !!perceive(cylinderLeft);
       !until(mock_called(setSpeeds(0, 10)), 2000);
       !assert_true(reachCylinder(true));
       -cylinderLeft; -+reachCylinder(false).
