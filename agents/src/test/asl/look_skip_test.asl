// Skill test of no second look around where the camera has just looked (skills/look-skip.asl): a
// full look around is recorded where it ends; a look point near a recent one leaves the round
// (unless none would be left) and, reached, gets no turn while the round holds another point, nor
// does the look every lookEvery ms made there; an old one counts for nothing. The
// operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/look-skip.asl") }
{ include("../../main/asl/skills/look-points.asl") }
{ include("../../main/asl/skills/sweep.asl") }

lookSkip(0.6, 120000).       // navigation's
lookSpacing(1).
arena(3, 2).
storagePoint(1, 0.5).
storageClearance(0.15).
location(0.9, 0, -0.4).

mock_operation(computeAngle(_, _, _, _, 45), ok).
mock_operation(_, ok).

// sweep's look around is 6.8 s (no maxSpeed here): this one instead
+!lookAround <- +looked.
// heading's, for the step towards a point
+!balance.
+!aimAt(X, Z) <- -+aim(X, Z).

@[test]
+!test_a_full_look_around_is_recorded_where_it_ends
    <- .abolish(lookedAt(_, _, _)); -+location(0.2, 0, -0.3);
       !lookAround;
       !assert_true(looked);
       !assert_true(lookedAt(0.2, -0.3, _)).

@[test]
+!test_a_look_point_near_a_recent_look_leaves_the_round
    <- .abolish(lookedAt(_, _, _)); .system_time(T); +lookedAt(-0.5, -0.4, T - 5000);
       -+location(-0.3, 0, -0.3); -+sweep([[-1, -0.5], [0, 0.5], [0, -0.5]]);
       !nextWaypoint;                                                   // (-1, -0.5) 0.51 m, (0, -0.5) 0.51 m away
       !assert_true(waypoint(0, 0.5, _));
       !assert_true(sweep([])).

@[test]
+!test_with_every_point_near_a_look_the_nearest_is_kept
    <- .abolish(lookedAt(_, _, _)); .system_time(T); +lookedAt(-0.5, -0.4, T - 5000);
       -+location(-0.3, 0, -0.3); -+sweep([[-1, -0.5], [0, -0.5]]);
       !nextWaypoint;
       !assert_true(waypoint(0, -0.5, _));
       !assert_true(sweep([[-1, -0.5]])).

@[test]
+!test_a_point_reached_near_a_recent_look_gets_no_turn
    <- .abolish(lookedAt(_, _, _)); -looked; .system_time(T); +lookedAt(0.5, -0.4, T - 5000);
       -+sweep([[-1, -0.5]]); -+waypoint(1, -0.5, 0); -+location(1, 0, -0.4);
       !sweepStep;
       !assert_false(looked);
       !assert_true(waypoint(-1, -0.5, _)).

@[test]
+!test_a_point_reached_near_a_recent_look_is_looked_at_when_the_round_has_no_other
    <- .abolish(lookedAt(_, _, _)); -looked; .system_time(T); +lookedAt(0.5, -0.4, T - 5000);
       -+sweep([[0.9, -0.3]]); -+waypoint(1, -0.5, 0); -+location(1, 0, -0.4);
       !sweepStep;                                                      // skipped, the round planned anew at once: a loop
       !assert_true(looked).

@[test]
+!test_an_old_look_counts_for_nothing
    <- .abolish(lookedAt(_, _, _)); -looked; .system_time(T); +lookedAt(0.5, -0.4, T - 130000);
       -+sweep([[-1, -0.5]]); -+waypoint(1, -0.5, 0); -+location(1, 0, -0.4);
       !sweepStep;
       !assert_true(looked);
       !assert_true(waypoint(-1, -0.5, _)).

@[test]
+!test_the_look_every_while_is_put_off_near_a_recent_look
    <- .abolish(lookedAt(_, _, _)); -looked; .system_time(T); +lookedAt(0.1, -0.3, T - 5000);
       -+lastLook(T - 30000); -+sweep([]); -+waypoint(-1, -0.5, T); -+closest(1000); -+location(0, 0, -0.3);
       !sweepStep;
       !assert_false(looked);
       !assert_true(lastLook(L) & L >= T);
       .abolish(lookedAt(_, _, _)); -+lastLook(T - 30000);
       !sweepStep;                                                      // no look near: the look around
       !assert_true(looked).
