// Skill test of recharge-trip.asl's parking in time (tidy-up's parkInTime), in a file of its own: the
// other low-battery tests run at once and send the robot to the charger. No robot, world or middleware
// (mock operations, see agents/README.md "Testing skills"). Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/suspend-resume.asl") }

arena(1.0, 1.0).
storagePoint(0.41, -0.41).
charger(-0.38, 0.38).
mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(computeAngle(_, _, _, _, 90), ok).
mock_operation(_, ok).

// an agent that parks in time (tidy-up: parkInTime) parks on the charger once the time left falls under
// S s a metre of the straight way to it and M s, whatever it counts as stored (a cylinder pushed into
// the storage area is not among its deliveries), while it searches, once the sweep has taken every waypoint
// of its lanes (a sign the count is wrong): 0.83 m from the charger, 32 s a metre and 15 s, 42 s
@[test]
+!test_an_agent_that_parks_in_time_parks_once_the_time_left_is_the_way_to_the_charger
    <- +orientation(90); !forget_calls; +parkInTime(32, 15);
       -+location(0.3, 0, -0.1); .system_time(T); +taskEnd(T + 60000);
       -battery(_); !!perceive(battery(700)); .wait(300);
       !assert_false(charging);                                      // 60 s left: searching on
       +~delivered; -taskEnd(_); .system_time(T2); +taskEnd(T2 + 30000);
       -battery(_); !!perceive(battery(699)); .wait(300);
       !assert_false(charging);                                      // a cylinder held: its delivery first
       -~delivered; -battery(_); !!perceive(battery(698)); .wait(300);
       !assert_false(charging);                                      // a cylinder found: not searching
       +searching; +picking; -battery(_); !!perceive(battery(697)); .wait(300);
       !assert_false(charging);                                      // a cylinder caught: its pick first
       -picking; -battery(_); !!perceive(battery(696)); .wait(300);
       !assert_false(charging);                                      // a pick just ended
       -+parkAfterPick(0); -battery(_); !!perceive(battery(695)); .wait(300);
       !assert_false(charging);                                      // no sign the count is wrong: searching on
       -+sweep([[0.5, 0.5], [-0.5, 0.5]]); -battery(_); !!perceive(battery(694)); .wait(300);
       !assert_false(charging);                                      // one waypoint of two taken
       -+sweep([[-0.5, 0.5], [0.5, 0.5]]); -battery(_); !!perceive(battery(693));
       !until(charging, 2000);
       !assert_true(charging);                                       // 30 s left: parking
       ?charger(Cx, Cz);
       !until(.intend(reachCharger), 10000);
       !assert_true(mock_called(setUpTargetPoint(Cx, 0, Cz)));
       !!perceive(targetReached);
       !until(mock_called(stopAcquireDistance), 10000);
       !assert_true(charging).                                       // parked for good
