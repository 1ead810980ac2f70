// Skill test of a knocked cylinder turned to (skills/knocked-aside.asl): right after a cylinder fell
// out of the gripper (lostBeside), the first obstacle a distance sensor shows is taken for it and the
// robot turns towards that side, holding avoidance and every move, until picking's reach takes it or
// the turn's time is out; later obstacles are left to avoidance. The operations are mocked.
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/knocked-aside.asl") }

maxSpeed(100).
reachCylinder(false).
mock_operation(_, ok).
// avoidance's lateral plan, for what the skill leaves to it
+lateralObstacle(_) <- +avoided.

// a knock, then the sensor's signal; each test starts afresh
+!knocked <- !forget_calls; -avoided; -+reachCylinder(false); -lostBeside; +lostBeside.

@[test]
+!test_a_cylinder_on_the_right_after_a_knock_is_turned_to
    <- !knocked; !!perceive(lateralObstacle("right")); -lateralObstacle("right");
       !until(mock_called(setSpeeds(25, -25)), 1000);
       !assert_true(mock_called(setSpeeds(25, -25)));
       !assert_true(avoiding);
       !assert_false(avoided);
       // picking's reach takes it: the turn ends without a stop, avoidance free again
       -+reachCylinder(true);
       !until(not avoiding, 1000);
       !assert_false(avoiding);
       !assert_false(mock_called(stop)).

@[test]
+!test_a_cylinder_on_the_left_after_a_knock_is_turned_to
    <- !knocked; !!perceive(lateralObstacle("left")); -lateralObstacle("left");
       !until(mock_called(setSpeeds(-25, 25)), 1000);
       !assert_true(mock_called(setSpeeds(-25, 25)));
       -+reachCylinder(true); !until(not avoiding, 1000).

@[test]
+!test_an_obstacle_ahead_on_the_left_after_a_knock_is_turned_to
    <- !knocked; -+delta(40); !!perceive(obstacle(true)); -obstacle(true);
       !until(mock_called(setSpeeds(-25, 25)), 1000);
       !assert_true(mock_called(setSpeeds(-25, 25)));
       -+reachCylinder(true); !until(not avoiding, 1000).

@[test]
+!test_a_turn_that_shows_nothing_stops_in_time
    <- -+knockedTurn(200); !knocked; !!perceive(lateralObstacle("right")); -lateralObstacle("right");
       !until(mock_called(stop), 1500);
       !assert_true(mock_called(stop));
       !assert_false(avoiding);
       -+knockedTurn(14000).

@[test]
+!test_an_obstacle_long_after_the_knock_is_avoided
    <- -+knockedAside(100); !knocked; .wait(300); !!perceive(lateralObstacle("right")); -lateralObstacle("right");
       !until(avoided, 1000);
       !assert_true(avoided);
       !assert_false(mock_called(setSpeeds(25, -25)));
       -+knockedAside(4500).
