// Skill: flank steering, not in the thesis. The MyBot's two sensors look 20° off its heading: a box
// they saw while the robot turned away from it leaves their sight before it leaves the robot's way,
// and the straight leg after the turn slid the flank along it (most of the wide arenas' contact).
// The middleware remembers the points the sensors met (flankWatch) and tells how sharply the robot
// must bend to pass clear of those in the strip its body sweeps (flankBend(K), 1/m, positive: to the
// right); a straight leg bends that way, by at most flankBendMax wheel units, while it lasts, and
// keeps its speed: no stop, no turn on the spot.
// Parameters:
// reach off the centre line (m: the 4.5 cm body and 1 cm), the side bent towards kept clear of
// points this far off the centre line (m), length ahead (m), memory (ms)
flankWatch(0.055, 0.10, 0.12, 2000).
flankBendMax(40).               // the largest wheel-speed difference of the bend
setUpGoal(setUpFlankSteer).
// Reads: cruiseSpeed(V), wheelGeometry(U, A), avoiding, veering (coverage's); obstacle, flankBend
// (the middleware's). Include it before coverage: its !cruise plan comes first.

@setUpFlankSteer +!setUpFlankSteer : flankWatch(R, C, L, K) <- flankWatch(R, C, L, K).

// a leg that begins with a point already in the strip (just after an avoidance) begins bent
@cruiseBent +!cruise : flankBend(K) & math.abs(K) > 0 & cruiseSpeed(V) <- !bend(K, V).
// atomic: no avoidance turn begins between the look at its beliefs and the wheels' command
@flankBendChange[atomic]
+flankBend(K) : .intend(leg(_)) & obstacle(false) & not avoiding & not veering & cruiseSpeed(V) <- !bend(K, V).
@bendAway
+!bend(K, V) : wheelGeometry(_, A) & flankBendMax(M)
    <- D = math.min(M, math.abs(K) * A * V); if (K > 0) { setSpeeds(V, V - D) } else { setSpeeds(V - D, V) }.
