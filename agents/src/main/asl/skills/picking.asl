// Skill: picking a red cylinder up (thesis Chapter 4 §2), with the Khepera's gripper and camera.
// A cylinder seen ahead (central sensor and camera: cylinderDetected) is picked: stop, catch (open
// and lower the gripper, close it), check the grip within a time limit (caught), raise the arm and
// check it is up (picked), then !go_ahead. A lateral cylinder (cylinderLeft / cylinderRight) makes
// the robot turn towards it first; cylinderBeyond, once it is centred, makes it approach slowly
// (the listing's setSpeeds(M/5, M/5)) until cylinderDetected, 8 s at most. Failures: no grip in
// time (the cylinder moved away), the arm does not rise.
// Beliefs: reachCylinder(true|false), picking.
// Reads: maxSpeed(M); pickingOff (a rule other skills extend: no cylinder is taken while it holds,
// e.g. while delivering or charging).
// Needs: +!go_ahead : picked(true) (what to do with the cylinder: the agent's, or delivery's);
// !escape (recovery). Include it after avoidance, before far sight.
// Fixed from the listings: "+reachCylinder(b)" that added a second reachCylinder belief is
// "-+reachCylinder(b)"; the listing's "turnAround; .wait(20000)" before the slow approach would
// turn the robot's back on the cylinder it has just centred: left out.

{ include("gripper.asl") }

reachCylinder(false).

@reachLeft
+cylinderLeft : reachCylinder(false) & not picking & not pickingOff
    <- -+reachCylinder(true); .succeed_goal(move(_)); stop; .print("Left Cylinder"); setSpeeds(0, 10); !reach.
@reachRight
+cylinderRight : reachCylinder(false) & not picking & not pickingOff
    <- -+reachCylinder(true); .succeed_goal(move(_)); stop; .print("Right Cylinder"); setSpeeds(10, 0); !reach.
@approachCentred
+cylinderBeyond : reachCylinder(true) & maxSpeed(M)
    <- .print("cylinder beyond"); setSpeeds(M / 5, M / 5); !approach.

@approach +!approach <- .wait("+cylinderDetected", 8000).
@approachFailed -!approach <- .print("Reach lateral cylinder failed."); stop; -+reachCylinder(false).

@reachTurning +!reach : reachCylinder(true) <- .wait("+cylinderBeyond", 5000).
@reachCentred +!reach : reachCylinder(false) <- .wait("+cylinderDetected", 3000).
@reachFailed -!reach <- .print("Reach lateral cylinder failed."); -+reachCylinder(false).

@pickDetected
+cylinderDetected : not picking & not picked(true) & not pickingOff
    <- +picking; -+reachCylinder(false); .succeed_goal(move(_)); stop; .print("Cylinder detected"); catching; !block.
// Recovery, not in the thesis: a reach whose cylinder came in front while no cylinder is taken
// (the battery ran low meanwhile: pickingOff) ends there; its approach ended with the detection,
// and "reachCylinder(true)" kept every move waiting for the rest of the run (tidy-up world 140: from
// 48 s on, 0 of 2 stored)
@reachEndedOff +cylinderDetected : reachCylinder(true) & pickingOff <- -+reachCylinder(false).

@moveWhileReaching +!move(N) : reachCylinder(true) <- .wait("+reachCylinder(false)"); !move(N).
@moveWhilePicking +!move(N) : picking <- .wait("-picking"); .wait(50); !move(N).

/* The catch and the lift, with time limits (Chapter 4 §2.1) */

@block +!block <- .wait("+caught(true)", 5000); !pick.
@blockFailed -!block[error(E), error_msg(M)] <- println("block failed: ", E, " ", M); !pick.

@pickCaught +!pick : caught(true) <- arm_up; .wait("+picked(true)", 3500); !go_ahead.
@pickMissed +!pick <- .print("Cylinder not found"); open_grip; arm_up; turnAround; .wait(2000); -picking.
@pickFailed -!pick[error(E), error_msg(M)] <- .print("pick failed: ", E, " ", M); !go_ahead.

// Recovery, not in the thesis: the listing stops here for good, "picking" still believed, and
// every move waited for "-picking"; the robot lets go, turns away and looks again.
@pickGaveUp
+!go_ahead : not picked(true)
    <- println("Cylinder picking failed"); stop; open_grip; arm_up; -picking; +avoiding; !escape; -avoiding.
