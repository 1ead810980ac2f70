// Skill tests of the following distance between teammates (skills/team-follow.asl, in
// team-delivery.asl): a robot on its way to the storage point stops behind a teammate that is
// ahead of it, too close and nearer the storage point, and goes on once that teammate is far
// enough; the teammate nearer the point never waits for the one behind; a wait behind a teammate
// that stands in no queue is bounded. Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(1.0, 1.0).
storagePoint(0.41, -0.41).
storageRadius(0.1).
charger(-0.38, 0.38).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(_, ok).

@[test]
+!test_the_robot_behind_waits_and_goes_on_when_the_way_is_clear
    <- !forget_calls; +storageQueue([]); +chargerQueue([]); -+targetPoint(0.41, -0.41);
       +location(-0.1, 0, 0.1); +orientation(315); +delivering;   // heading for the storage point
       !!perceive(robotAt(khepera1, 0.0, 0.0));                  // 0.14 m ahead, nearer the point
       !until(following(_), 3000);
       !assert_true(following(khepera1));
       !assert_true(mock_called(stop));
       !assert_true(halted);                                      // the steering stands still
       .wait(400);
       !assert_true(following(khepera1));                         // still there: it waits
       !forget_calls;
       -robotAt(khepera1, _, _); !!perceive(robotAt(khepera1, 0.16, -0.16));   // 0.37 m ahead now
       !until(not following(_), 3000);
       !assert_false(following(_));
       // the heading comes a few reasoning steps after the wait ends, in the skill's own intention:
       // waited for (bounded), not raced, and that intention is over before the next test
       !until(mock_called(computeAngle(_, _, 0.41, -0.41, _)), 3000);
       !assert_true(mock_called(computeAngle(_, _, 0.41, -0.41, _)));          // heads on again
       !until(not .intend(followResume), 3000);
       .drop_desire(balance); .drop_desire(steer); -robotAt(khepera1, _, _).

@[test]
+!test_the_robot_nearer_the_point_goes_on
    <- !forget_calls; -location(_, _, _); +location(0.0, 0, 0.0);
       !!perceive(robotAt(zeta, -0.1, 0.1));                      // 0.14 m behind, farther from the point
       .wait(400);
       !assert_false(following(_));
       !assert_false(mock_called(stop));
       -robotAt(zeta, _, _).

@[test]
+!test_a_wait_behind_a_teammate_in_no_queue_is_bounded
    <- !forget_calls; -location(_, _, _); +location(-0.1, 0, 0.1); -+followTime(600);
       !!perceive(robotAt(khepera1, 0.0, 0.0));
       !until(following(_), 3000);
       !assert_true(following(khepera1));
       !until(not following(_), 3000);                            // the teammate does not move
       !assert_false(following(_));
       !assert_true(followedOut(khepera1));                        // passed by for a while
       .drop_desire(balance); .drop_desire(steer); -robotAt(khepera1, _, _).

@[test]
+!test_a_robot_not_on_its_way_keeps_no_distance
    <- !forget_calls; -delivering; -followedOut(_);
       !!perceive(robotAt(khepera1, 0.0, 0.0));
       .wait(400);
       !assert_false(following(_));
       -robotAt(khepera1, _, _).
