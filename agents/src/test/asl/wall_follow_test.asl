// Skill test of the wall following for the MyBot (skills/wall-follow.asl): in an agent that turns
// it on, once new floor stops coming while the crossed floor spans a small part of the arena, the
// robot follows the wall on the side that reads more, keeping that reading in the band; not in a
// hall, and not in an agent that does not turn it on. The operations are mocked (agents/README.md
// "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/wall-follow.asl") }
{ include("../../main/asl/skills/coverage.asl") }

maxSpeed(100).
arena(3, 3).                 // 9 m2, a diagonal of 4.24 m
mock_operation(_, ok).
obstacle(false).

@[test]
+!test_a_used_up_room_starts_a_follow_of_the_wall_on_the_side_that_reads_more
    <- !forget_calls; -+obstacleTimes([]); -following(_, _, _); -nextFollowLook(_); -+followWindow(1); // the test's clock is young
       +followWalls; -+leftSensor(60); -+rightSensor(0);
       +mock_operation(freshCells(1, 2), ok); +mock_operation(visitedSpan(2), ok);   // 2 m of 4.24
       +mock_operation(headingTurned(0), ok);
       !!move(0.8);
       !until(mock_called(setSpeeds(_, _)), 2000);
       .drop_desire(move(_));
       -mock_operation(freshCells(1, 2), ok); -mock_operation(visitedSpan(2), ok); -mock_operation(headingTurned(0), ok);
       -+followWindow(30000); -followWalls;
       !assert_true(following(_, _, left));
       !assert_true(mock_called(setSpeeds(100, 100)));        // 60 is within the band: straight on
       -following(_, _, _); -nextFollowLook(_).

@[test]
+!test_a_reading_over_the_band_bears_away_from_the_wall
    <- !forget_calls; -+obstacleTimes([]); .system_time(T); +following(T + 10000, 0, right); -+rightSensor(150);
       +mock_operation(headingTurned(0), ok); +mock_operation(freshCells(10000, 0), ok);
       !!move(0.8);
       !until(mock_called(setSpeeds(_, _)), 2000);
       .drop_desire(move(_));
       -mock_operation(headingTurned(0), ok); -mock_operation(freshCells(10000, 0), ok); -following(_, _, _);
       !assert_true(mock_called(setSpeeds(50, 100))).          // the right wheel faster: away from the wall on the right

@[test]
+!test_a_follow_that_turned_a_full_circle_towards_its_wall_ends
    <- !forget_calls; -+obstacleTimes([]); .system_time(T); +following(T + 10000, 0, right); -+rightSensor(50);
       +mock_operation(headingTurned(-500), ok);               // 500 degrees to the right: round a box
       +mock_operation(freshCells(10000, 0), ok);
       +mock_operation(exploreTurn(100, "left", 50), ok); +mock_operation(staleTime(0), ok);
       !!move(0.8);
       !until(not following(_, _, _), 2000);
       .drop_desire(move(_));
       -mock_operation(headingTurned(-500), ok); -mock_operation(exploreTurn(100, "left", 50), ok);
       -mock_operation(staleTime(0), ok); -mock_operation(freshCells(10000, 0), ok); -nextFollowLook(_);
       !assert_false(following(_, _, _)).

@[test]
+!test_no_follow_in_a_hall
    <- !forget_calls; -+obstacleTimes([]); -following(_, _, _); -nextFollowLook(_); -+followWindow(1); -stale;
       +followWalls;
       +mock_operation(freshCells(1, 2), ok); +mock_operation(visitedSpan(4), ok);   // 4 m of 4.24: the whole arena
       +mock_operation(exploreTurn(100, "left", 50), ok); +mock_operation(staleTime(0), ok); +mock_operation(headingTurned(0), ok);
       !!move(0.8);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       .drop_desire(move(_));
       -mock_operation(freshCells(1, 2), ok); -mock_operation(visitedSpan(4), ok); -mock_operation(headingTurned(0), ok);
       -mock_operation(exploreTurn(100, "left", 50), ok); -mock_operation(staleTime(0), ok);
       -+followWindow(30000); -followWalls; -nextFollowLook(_);
       !assert_true(mock_called(visitedSpan(_)));
       !assert_false(following(_, _, _)).

@[test]
+!test_no_follow_in_an_agent_that_does_not_turn_it_on
    <- !forget_calls; -+obstacleTimes([]); -following(_, _, _); -nextFollowLook(_); -+followWindow(1); -stale;
       +mock_operation(freshCells(1, 2), ok); +mock_operation(visitedSpan(2), ok);
       +mock_operation(exploreTurn(100, "left", 50), ok); +mock_operation(staleTime(0), ok); +mock_operation(headingTurned(0), ok);
       !!move(0.8);
       !until(mock_called(setSpeeds(100, 100)), 2000);
       .drop_desire(move(_));
       -mock_operation(freshCells(1, 2), ok); -mock_operation(visitedSpan(2), ok); -mock_operation(headingTurned(0), ok);
       -mock_operation(exploreTurn(100, "left", 50), ok); -mock_operation(staleTime(0), ok);
       -+followWindow(30000);
       !assert_false(mock_called(freshCells(_, _)));
       !assert_false(following(_, _, _)).
