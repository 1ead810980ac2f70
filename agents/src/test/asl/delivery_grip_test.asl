// Skill test of the put-down at the storage point with the gripper's point (skills/delivery.asl with
// skills/gripper.asl): a robot whose centre reached the storage point but whose gripper's point lies
// outside the storage area (it came past the point sideways) turns to the storage point before it
// puts the cylinder down; one whose gripper's point is inside puts down at once. The operations are mocked.
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/delivery.asl") }
{ include("../../main/asl/skills/gripper.asl") }

maxSpeed(100).
travelSpeed(100).           // far sight's
quickTurns.                 // the agent's: turns on the spot
storagePoint(0.4, -0.4).    // the world's, as the launcher gives them
storageRadius(0.06).

// the storage point's heading from the robot's place below is 236 degrees
mock_operation(computeAngle(0.42, -0.37, 0.4, -0.4, 236), ok).
mock_operation(_, ok).

+!avoid(D) <- -avoiding.
+!escape.
+!found.
+!nextWaypoint.
+!move(N).

@[test]
+!test_a_gripper_point_outside_the_area_turns_the_robot_to_the_storage_point_before_the_put_down
    <- !forget_calls; -+location(0.42, 0, -0.37); -+orientation(90); +delivering; -picked(true);
       // the centre 2 and 3 cm from the point; the gripper 5 cm ahead at (0.42, -0.32): 8.2 cm off
       !!perceive(targetReached);
       !until(mock_called(setSpeeds(50, -50)) | mock_called(setSpeeds(-50, 50)), 2000);
       !assert_true(desired(236));
       !assert_false(mock_called(putDown));                             // not yet: still turning
       -+orientation(236);                                              // facing the point: gripper at (0.39, -0.41)
       !until(mock_called(putDown), 2000);
       !assert_true(mock_called(putDown));
       !assert_true(stored(1));
       !until(desired(270), 2000);
       !assert_true(desired(270));                                      // leaves opposite its arrival heading
       -+orientation(270); !until(mock_called(waitExit), 2000);
       !!perceive(outOfStorageArea); !until(not ~delivered, 2000);
       -targetReached; -outOfStorageArea; -+stored(0).

@[test]
+!test_a_gripper_point_inside_the_area_puts_down_at_once
    <- !forget_calls; -+location(0.37, 0, -0.4); -+orientation(0); +delivering; -picked(true);
       // heading at the point: the gripper 5 cm ahead at (0.42, -0.4), 2 cm off
       !!perceive(targetReached);
       !until(mock_called(putDown), 2000);
       !assert_true(mock_called(putDown));
       !assert_false(mock_called(computeAngle(_, _, _, _, _)));        // no turn to the point
       !until(desired(180), 2000);
       -+orientation(180); !until(mock_called(waitExit), 2000);
       !!perceive(outOfStorageArea); !until(not ~delivered, 2000);
       -targetReached; -outOfStorageArea; -+stored(0).
