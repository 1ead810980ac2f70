// Skill test of an avoidance and picking together (skills/avoidance.asl, skills/recovery.asl,
// skills/picking.asl): an obstacle still seen when a move starts is avoided inside that move
// (recovery's @moveAvoidStill), and a cylinder seen meanwhile makes picking end the move
// (.succeed_goal(move(_))). The avoidance must not leave "avoiding" behind: every later move waits
// for it to go (wide worlds: robots stood still to the end of the run). The operations are mocked
// (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/avoidance.asl") }
{ include("../../main/asl/skills/picking.asl") }
{ include("../../main/asl/skills/recovery.asl") }

maxSpeed(100).
avoidTimeout(3000).
mock_operation(_, ok).

// what picking needs of the agent: the cylinder held is handed on
+!go_ahead : picked(true) <- +handedOn; -picking.
// random motion (the last +!move plan, as random-walk.asl's), and the motion loop (initial phase's)
+!move(N) <- +moved(N); .wait(50).
// a test waits for its loop to end (loopEnded) before the next test starts one of its own
+!motion_loop <- -loopEnded; while (not loopOff) { !move(0.4) }; +loopEnded.

// an obstacle seen before the move starts (its +obstacle(true) event long handled): the move avoids it
+!obstacle_still_seen(D) <- -+delta(D); +avoiding; -obstacle(false); +obstacle(true); -avoiding.
+!obstacle_gone <- -obstacle(true); !!perceive(obstacle(false)).

@[test]
+!test_a_lateral_reach_during_an_avoidance_inside_a_move_leaves_no_avoiding_behind
    <- !forget_calls; -moved(_); -loopOff; !obstacle_still_seen(0);
       !!motion_loop;
       !until(mock_called(turnAround), 2000);                        // the avoidance inside the move
       !assert_true(avoiding);
       !!perceive(cylinderLeft);                                      // picking ends the move
       !until(mock_called(setSpeeds(0, 10)), 2000);
       !obstacle_gone;
       !!perceive(cylinderBeyond); !!perceive(cylinderDetected);      // the reach ends in a catch
       !until(mock_called(catching), 2000);
       .drop_desire(block); -picking;
       !until(not avoiding, 4000);
       !assert_false(avoiding);
       -moved(_); !until(moved(_), 2000);                             // and random motion goes on
       !assert_true(moved(0.4));
       +loopOff; !until(loopEnded, 2000); !assert_true(loopEnded);
       -cylinderLeft; -cylinderBeyond; -cylinderDetected.

@[test]
+!test_a_cylinder_caught_during_an_avoidance_inside_a_move_leaves_no_avoiding_behind
    <- !forget_calls; -moved(_); -loopOff; -+reachCylinder(false); !obstacle_still_seen(40);
       !!motion_loop;
       !until(mock_called(setSpeeds(50, -50)), 2000);
       !assert_true(avoiding);
       !!perceive(cylinderDetected);                                  // picking ends the move
       !until(mock_called(catching), 2000);
       !obstacle_gone;
       !!perceive(caught(true)); !until(mock_called(arm_up), 2000);
       !!perceive(picked(true)); !until(handedOn, 2000);
       !until(not avoiding, 4000);
       !assert_false(avoiding);
       +loopOff; !until(loopEnded, 2000); !assert_true(loopEnded);
       -picked(true); -caught(true); -cylinderDetected.

// an avoidance that is not cut off still ends the move only once it is over
@[test]
+!test_an_obstacle_still_seen_is_avoided_before_the_move_ends
    <- !forget_calls; -moved(_); -ended; !obstacle_still_seen(0);
       !!move_and_note(0.3);
       !until(mock_called(turnAround), 2000);
       .wait(200);
       !assert_false(ended);
       !assert_true(avoiding);
       !obstacle_gone;
       !until(ended, 2000);
       !assert_true(ended);
       !assert_false(avoiding).
+!move_and_note(N) <- !move(N); +ended.
