// Skill test of a knocked cylinder turned to (skills/knocked-aside.asl): right after a cylinder fell
// out of the gripper (lostBeside), the first obstacle a distance sensor shows is taken for it and the
// robot turns towards that side, holding avoidance, every move and picking's lateral reach, until the
// camera's centre shows the cylinder, then approaches it slowly until picking's detection takes it, or
// the time is out; later obstacles are left to avoidance. The operations are mocked.
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/knocked-aside.asl") }

maxSpeed(100).
reachCylinder(false).
mock_operation(_, ok).
// avoidance's lateral plan and picking's reach, for what the skill leaves to them
+lateralObstacle(_) <- +avoided.
+cylinderRight <- +reached.

// a knock, then the sensor's signal; each test starts afresh
+!knocked <- !forget_calls; -avoided; -reached; -picking; -obstacle(true); -+reachCylinder(false); -lostBeside; +lostBeside.

@[test]
+!test_a_cylinder_on_the_right_after_a_knock_is_turned_to
    <- !knocked; !!perceive(lateralObstacle("right")); -lateralObstacle("right");
       !until(mock_called(setSpeeds(25, -25)), 1000);
       !assert_true(mock_called(setSpeeds(25, -25)));
       !assert_true(avoiding);
       !assert_false(avoided);
       // picking's detection takes it: the turn ends without a stop, avoidance free again
       +picking;
       !until(not avoiding, 1000);
       !assert_false(avoiding);
       !assert_false(mock_called(stop)).

@[test]
+!test_a_cylinder_on_the_left_after_a_knock_is_turned_to
    <- !knocked; !!perceive(lateralObstacle("left")); -lateralObstacle("left");
       !until(mock_called(setSpeeds(-25, 25)), 1000);
       !assert_true(mock_called(setSpeeds(-25, 25)));
       +picking; !until(not avoiding, 1000).

@[test]
+!test_an_obstacle_ahead_on_the_left_after_a_knock_is_turned_to
    <- !knocked; -+delta(40); !!perceive(obstacle(true)); -obstacle(true);
       !until(mock_called(setSpeeds(-25, 25)), 1000);
       !assert_true(mock_called(setSpeeds(-25, 25)));
       +picking; !until(not avoiding, 1000).

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

@[test]
+!test_a_cylinder_ahead_after_the_turn_is_approached_not_reached_for
    <- !knocked; !!perceive(lateralObstacle("right")); -lateralObstacle("right");
       !until(mock_called(setSpeeds(25, -25)), 1000);
       // the camera shows it on its side: picking's reach is held back, the turn goes on
       !!perceive(cylinderRight); -cylinderRight; .wait(100);
       !assert_false(reached);
       !assert_false(mock_called(setSpeeds(20, 20)));
       // then in its centre: a little more turn, then the slow approach
       !!perceive(cylinderBeyond); -cylinderBeyond;
       !until(mock_called(setSpeeds(20, 20)), 1500);
       !assert_true(mock_called(setSpeeds(20, 20)));
       !assert_true(avoiding);
       +picking; !until(not avoiding, 1000);
       !assert_false(avoiding);
       !assert_false(turningToKnocked);
       // picking's reach is free again after the turn
       -cylinderRight; !perceive(cylinderRight); !until(reached, 500);
       !assert_true(reached).

@[test]
+!test_an_approach_that_detects_nothing_stops_in_time
    <- -+knockedApproach(100, 200); !knocked; !!perceive(lateralObstacle("left")); -lateralObstacle("left");
       !until(mock_called(setSpeeds(-25, 25)), 1000);
       !!perceive(cylinderBeyond); -cylinderBeyond;
       !until(mock_called(stop), 1500);
       !assert_true(mock_called(setSpeeds(20, 20)));
       !assert_true(mock_called(stop));
       !assert_false(avoiding);
       !assert_false(knockedAhead);
       -+knockedApproach(500, 3000).
