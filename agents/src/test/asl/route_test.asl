// Skill test of the way through the robot's own map (skills/route.asl with heading.asl): the robot
// heads for the route's point on the way, not for the target behind the obstacles it met; near
// the target it heads for the target itself; the boundary following of way-round stands aside; with
// routeHold the sweep keeps its point until it is reached or an obstacle met.
// The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/route.asl") }
{ include("../../main/asl/skills/way-round.asl") }
{ include("../../main/asl/skills/heading.asl") }

maxSpeed(100).
arena(2, 2).
location(0, 0, 0).
orientation(0).
targetPoint(0.9, 0.4).
leftSensor(0).
rightSensor(0).
travelling :- delivering.

// the map's route to (0.9, 0.4) bends at (0.2, -0.3); headings: 300 degrees to the bend, 24 to the target
mock_operation(routeTo(0.9, 0.4, 0.2, -0.3), ok).
mock_operation(computeAngle(_, _, 0.2, -0.3, 300), ok).
mock_operation(computeAngle(_, _, 0.9, 0.4, 24), ok).
mock_operation(_, ok).

@[test]
+!test_the_heading_is_for_the_routes_point_on_the_way
    <- !forget_calls; !computeGap;
       !assert_true(mock_called(routeTo(0.9, 0.4, _, _)));
       !assert_true(aim(0.2, -0.3));
       !assert_true(desired(300)).

@[test]
+!test_near_the_target_the_heading_is_for_the_target_itself
    <- !forget_calls; -+location(0.8, 0, 0.3); !computeGap;
       !assert_false(mock_called(routeTo(_, _, _, _)));
       !assert_true(desired(24));
       -+location(0, 0, 0).

@[test]
+!test_the_sweep_and_the_trips_ask_the_same_way
    <- !aimAt(0.9, 0.4); !assert_true(aim(0.2, -0.3)).

@[test]
+!test_no_boundary_following_while_the_route_is_planned
    <- +delivering; -+detours(0); -+detours(1); -+detours(2);
       +obstacle(true);
       .wait(100);
       !assert_false(followingWall(_, _, _));
       -delivering; -obstacle(true).

// routeHold: the sweep keeps its planned point until it is within routeReach of it or an obstacle
// was avoided since it was planned
@[test]
+!test_a_held_point_is_kept_until_reached_or_an_obstacle_met
    <- +routeHold(600000); -aimChosen(_, _, _); -lastAvoid(_);
       !aimAt(0.9, 0.4); !assert_true(aim(0.2, -0.3));
       !forget_calls; !aimAt(0.9, 0.4);
       !assert_false(mock_called(routeTo(_, _, _, _)));
       -+location(0.15, 0, -0.25); !forget_calls; !aimAt(0.9, 0.4);
       !assert_true(mock_called(routeTo(0.9, 0.4, _, _)));
       -+location(0, 0, 0); !forget_calls; !aimAt(0.9, 0.4);
       !assert_false(mock_called(routeTo(_, _, _, _)));
       .system_time(T); +lastAvoid(T); !forget_calls; !aimAt(0.9, 0.4);
       !assert_true(mock_called(routeTo(0.9, 0.4, _, _)));
       -routeHold(_); -lastAvoid(_); -aimChosen(_, _, _).

// an agent's wallGuess and wallFirm (suspend/resume's): the map's guess is set up, and made firm for
// wallFirm's metres; without wallGuess no firm part
@[test]
+!test_a_firm_wall_guess_is_set_up_with_the_guess
    <- +wallGuess(1.0); +wallFirm(0.15); !forget_calls; !setUpRoute;
       !assert_true(mock_called(routeWallGuess(1.0)));
       !assert_true(mock_called(routeWallFirm(0.15)));
       -wallGuess(_); !forget_calls; !setUpRoute;
       !assert_false(mock_called(routeWallFirm(_)));
       -wallFirm(_).
