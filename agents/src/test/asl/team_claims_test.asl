// Skill tests of the team's claims (skills/team-claims.asl, in team-delivery.asl): a cylinder
// sighted is claimed on the task board at its estimated place before the robot homes on it; one
// another robot has claimed is ignored and not homed on. Artifact operations are mocked (see
// agents/README.md "Testing skills"). Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(1.0, 1.0).
storagePoint(0.41, -0.41).
storageRadius(0.1).
charger(-0.38, 0.38).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(claim(_, _, 3), ok).
mock_operation(_, ok).

@[test]
+!test_a_sighted_cylinder_is_claimed_at_its_estimated_place_then_homed_on
    <- +location(0.1, 0, 0.2); +orientation(90);
       !!perceive(cylinderSighted(0, 0.5));              // straight ahead, half a metre away
       !until(homing(_), 5000);
       ?mock_called(claim(X, Z, 3));
       !assert_true(X > 0.09 & X < 0.11 & Z > 0.69 & Z < 0.71);
       !assert_true(myClaim(3)).

@[test]
+!test_a_cylinder_claimed_by_another_robot_is_ignored_and_not_homed_on
    <- -homing(_); -myClaim(_); .abolish(mock_called(_));
       .abolish(mock_operation(_, _));                    // only these two from now on
       +mock_operation(claim(_, _, _), fail("khepera2 has claimed it", claimed_by(khepera2, 5)));
       +mock_operation(ignoreCylindersNear(_, _, _), ok);
       !!perceive(cylinderSighted(-10, 0.8));
       !until(mock_called(ignoreCylindersNear(_, _, _)), 5000);
       !assert_true(mock_called(ignoreCylindersNear(_, _, 0.15)));
       !assert_false(homing(_));
       !assert_false(myClaim(_)).

+!perceive(B) <- -B; +B.

+!until(C, _) : C.
+!until(C, T) : T > 0 <- .wait(20); !until(C, T - 20).
