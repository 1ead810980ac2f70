// Skill test of the side of a wall chosen from the trail (skills/trail-side.asl): a trail point every
// trailStep driven; the most recent one past the wall met (by trailPast, or by trailPastAlong for a
// point laid while following a wall) gives the side to follow (the way the robot came), unless that
// side was given up; with none, way-round's own choice. The operations are
// mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/trail-side.asl") }

trailStep(0.1).              // navigation's
location(0, 0, 0).
goingTo(1, 0.2).             // way-round's rule: the target, mostly along +x from the robot

// the robot faces +x (0 degrees): its left is -z
mock_operation(computeAngle(_, _, _, _, 0), ok).
mock_operation(_, ok).

// way-round's plans the skill needs: its own choice, and the other side
+!chooseSide(blind).
+!otherSide(right, left).
+!otherSide(left, right).

@[test]
+!test_a_point_is_kept_every_trail_step_driven
    <- .abolish(trail(_, _, _)); .abolish(trailLast(_, _, _)); -+location(0, 0, 0);
       !setUpTrailSide;
       -+location(0, 0, 0.3);                                           // the first GPS reading
       !until(trailLast(0, _, _), 2000);
       !assert_true(trail(0, 0, 0.3));                                  // not the (0, 0) before it
       -+location(0.05, 0, 0.3);
       .wait(1200);
       !assert_false(trail(1, _, _));                                   // 5 cm: no point
       -+location(0.2, 0, 0.3);
       !until(trail(1, 0.2, 0.3), 2000);
       !assert_true(trail(1, 0.2, 0.3)).

@[test]
+!test_the_way_came_past_the_wall_gives_the_side
    <- .abolish(trail(_, _, _)); -+location(0, 0, 0); -gaveUpSide(_);
       +trail(1, 0.5, -0.8); +trail(2, -0.3, -0.5);                     // came through a doorway at z -0.8
       !chooseSide(S1);
       !assert_equals(right, S1);                                       // to the left: the wall on the right
       +trail(3, 0.4, 0.6);                                             // since then past it at z 0.6
       !chooseSide(S2);
       !assert_equals(left, S2).

@[test]
+!test_no_point_past_the_wall_leaves_the_choice_to_way_round
    <- .abolish(trail(_, _, _)); -+location(0, 0, 0); -gaveUpSide(_);
       +trail(1, 0.1, -0.8); +trail(2, -0.6, 0.5);                      // 0.1 m along x: not past it
       !chooseSide(S);
       !assert_equals(blind, S).

@[test]
+!test_a_side_given_up_is_not_taken_again
    <- .abolish(trail(_, _, _)); -+location(0, 0, 0);
       +trail(1, 0.5, -0.8); +gaveUpSide(right);
       !chooseSide(S);
       !assert_equals(left, S);
       -gaveUpSide(right).

@[test]
+!test_a_point_laid_while_following_a_wall_is_marked_along
    <- .abolish(trailAlong(_, _, _)); -+location(1, 0, 1);
       if (not trailLast(_, _, _)) { !setUpTrailSide };                 // the clock, if no test started it
       !until(trail(_, 1, 1), 2000);
       !assert_false(trailAlong(_, _, _));                              // not following: a plain point
       +followingWall(left, 0, 1);
       -+location(1.2, 0, 1);
       !until(trail(_, 1.2, 1), 2000);
       !assert_true(trailAlong(_, 1.2, 1));
       -followingWall(left, 0, 1); .abolish(trail(_, _, _)); .abolish(trailAlong(_, _, _)).

// a thin wall's two faces are some 0.1 m apart along the axis: the robot that followed the far face
// to the doorway (to its right, z 0.7) goes back that way, not by an older point past the other end
@[test]
+!test_the_far_face_of_a_thin_wall_followed_counts_as_past_it
    <- .abolish(trail(_, _, _)); .abolish(trailAlong(_, _, _)); -+location(0, 0, 0); -gaveUpSide(_);
       +trail(1, 0.5, -1.2);                                            // long ago, past the wall's other end
       +trail(2, 0.1, 0.3); +trailAlong(2, 0.1, 0.3); +trail(3, 0.1, 0.7); +trailAlong(3, 0.1, 0.7);
       !chooseSide(S);
       !assert_equals(left, S);
       .abolish(trail(_, _, _)); .abolish(trailAlong(_, _, _)).

// a point 0.1 m past not laid along a wall is where the robot was before it drove to a box: not past it
@[test]
+!test_a_near_point_not_laid_along_a_wall_is_not_past_it
    <- .abolish(trail(_, _, _)); .abolish(trailAlong(_, _, _)); -+location(0, 0, 0); -gaveUpSide(_);
       +trail(1, 0.1, 0.7);
       !chooseSide(S);
       !assert_equals(blind, S);
       .abolish(trail(_, _, _)).
