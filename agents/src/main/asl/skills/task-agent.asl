// Skill: the task agent of a robot shared with an energy agent (not in the thesis: its Chapter 6
// wish). The task agent holds the wheels from its start; when the energy agent asks it to suspend
// (.send(T, achieve, suspend)) it suspends what runs ("charging", suspension.asl), stops the robot
// and releases the wheels; when asked to resume, it takes them back, heads for the storage point
// again and resumes (-charging). A cylinder that falls meanwhile is dealt with on resuming.
// Needs: shared-wheels.asl, suspension.asl, delivery (the target point, ray). Include it after
// shared-wheels.asl and before suspension.asl.

setUpGoal(holdWheels).

@holdWheels +!holdWheels <- acquireWheels.

// what moves the robot ends here (a new move, pick or delivery step waits for -charging)
@suspendOnRequest
+!suspend[source(A)]
    <- +charging; .succeed_goal(move(_)); .drop_intention(balance); .drop_intention(detour(_));
       .drop_intention(avoid(_)); .drop_intention(escape); -avoiding; if (not wheelsNotMine) { stop };
       releaseWheels;
       .print("Task suspended: the wheels go to ", A).
@resumeOnRequest
+!resume[source(A)]
    <- acquireWheels; .print("Task resumed: the wheels are back from ", A); !restoreTarget; -charging; !afterFall.

// a cylinder that fell while the wheels were another's: what a fall does, now that they are ours
@fallenNotMine +fallen : wheelsNotMine <- +fellMeanwhile.
@fallenMeanwhile +!afterFall : fellMeanwhile <- -fellMeanwhile; +fallen; -fallen.
@noFallMeanwhile +!afterFall.
