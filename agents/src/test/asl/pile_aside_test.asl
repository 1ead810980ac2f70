// Skill test of the stored pile seen aside (skills/knocked-aside.asl with picking.asl, tidy-up's): red in
// a side section while the pile lies ahead on that side within pileAsideWithin begins no lateral reach;
// red on the other side, the pile farther away, nothing stored yet, or a fetch after a fall by the
// storage area reach as picking always does. The operations are mocked.
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/knocked-aside.asl") }
{ include("../../main/asl/skills/picking.asl") }

maxSpeed(100).
storagePoint(0, 0).
storageRadius(0.06).
stored(2).
mock_operation(_, ok).
+!escape.

// the robot at (X, Z) facing O; a side signal; did picking's reach begin (its turn)?
+!seen(X, Z, O, S) <- !forget_calls; -+reachCylinder(false); -+location(X, 0, Z); -+orientation(O); !!perceive(S); .wait(100); -S.
reached :- mock_called(setSpeeds(0, 10)) | mock_called(setSpeeds(10, 0)).

@[test]
+!test_the_pile_ahead_left_or_right_is_not_reached_for
    <- // 0.16 m from the point, which lies at 342 degrees from the robot; facing 14, 32 degrees left of the heading
       !seen(-0.15, 0.05, 14, cylinderLeft); !assert_false(reached); !assert_true(reachCylinder(false));
       !assert_true(pileOnSide("left")); !assert_false(pileOnSide("right"));
       // facing 315: 27 degrees right
       !seen(-0.15, 0.05, 315, cylinderRight); !assert_false(reached).

@[test]
+!test_red_away_from_the_pile_is_reached_for
    <- // the pile on the left, red on the right
       !seen(-0.15, 0.05, 14, cylinderRight); !assert_true(reached);
       // the pile 63 degrees left, beside the camera's field
       !seen(-0.15, 0.05, 45, cylinderLeft); !assert_true(reached);
       // the pile 0.3 m away
       !seen(-0.3, 0.05, 10, cylinderRight); !assert_true(reached);
       // the pile behind
       !seen(-0.15, 0.05, 200, cylinderLeft); !assert_true(reached);
       // nothing stored yet
       -+stored(0); !seen(-0.15, 0.05, 14, cylinderLeft); !assert_true(reached); -+stored(2);
       // a fetch just after a fall by the storage area
       .system_time(T); +fellNearStorageAt(T);
       !seen(-0.12, 0.05, 14, cylinderLeft); !assert_true(reached); -fellNearStorageAt(_).
