// Skill: every cylinder knocked out of the gripper is turned to, not avoided, not in the thesis. It
// lies beside the robot (search-memory's lostBeside): the knock is noted (knockedAt) for knock-fetch.asl,
// which turns the robot towards the first obstacle a distance sensor shows after it (avoidance turned
// the robot away from it, again and again, and the sweep drove off: tidy-up world 204 × 2, found again
// 138 s later). Without this skill only a fall by the storage area is turned to (delivery notes it).
// Reads: lostBeside (search-memory's, added when a delivery ends outside the storage area).
// Beliefs: knockedAt(T).
// Needs: search-memory (@backOffFirst), avoidance. Include it after delivery, before avoidance: it
// includes knock-fetch.asl (the turn, and the fetch by the storage area).

@knockedBeside +lostBeside <- .system_time(T); -+knockedAt(T).
{ include("knock-fetch.asl") }
