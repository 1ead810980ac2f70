// Skill tests of the task agent of experiment 4's robot split between two agents
// (suspend-resume-task.asl; docs/teams.md, "One robot, two agents"): while it holds the wheels it
// avoids an obstacle as experiment 4 does; asked to suspend, it stops the robot, releases the
// wheels and leaves obstacles alone while they are another agent's; asked to resume, it takes
// them back and heads for the storage point again. The operations are mocked (agents/README.md
// "Testing skills"), the percepts are added as beliefs. Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("../../main/asl/suspend-resume-task.asl") }

// the world's landmarks, as the launcher gives them
arena(1.0, 1.0).
storagePoint(0.41, -0.41).
charger(-0.38, 0.38).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(computeAngle(_, _, _, _, 90), ok).
mock_operation(_, ok).

@[test]
+!test_an_obstacle_is_avoided_while_the_wheels_are_its_own
    <- .my_name(Me); +wheels(Me); +delta(0); !!perceive(obstacle(true));
       !until(mock_called(backward), 3000);
       !assert_true(mock_called(backward)).

@[test]
+!test_asked_to_suspend_it_stops_releases_the_wheels_and_leaves_obstacles_alone
    <- !until(not avoiding, 12000); -obstacle(true); .abolish(mock_called(_));
       !suspend;
       !assert_true(charging);
       !assert_true(mock_called(stop));
       !assert_true(mock_called(releaseWheels));
       -+wheels(energy); .abolish(mock_called(_));                 // the energy agent has them
       !!perceive(obstacle(true));
       .wait(300);
       !assert_false(mock_called(backward));
       !assert_false(mock_called(stop)).

@[test]
+!test_asked_to_resume_it_takes_the_wheels_back_and_heads_for_the_storage_point
    <- .my_name(Me); !resume; -+wheels(Me);
       ?storagePoint(X, Z);
       !assert_true(mock_called(acquireWheels));
       !assert_true(mock_called(setUpTargetPoint(X, 0, Z)));
       !assert_false(charging).

// a percept, in an intention of its own (as the architecture would add it)
+!perceive(B) <- +B.

// waits (polling, at most T ms) until the condition holds
+!until(C, _) : C.
+!until(C, T) : T > 0 <- .wait(20); !until(C, T - 20).
+!until(_, _).
