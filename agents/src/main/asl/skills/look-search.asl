// Skill: the parameters of the search by look points that navigation and suspend/resume share, not
// in the thesis (look-points.asl and look-skip.asl read them; object picking sets its own spacing).
// An agent that includes it searches by look points; include it among the agent's parameters, and
// look-skip.asl and look-points.asl after search memory and before sweep.
// Parameters:
// the sweep heads for look points at most this far apart (m) and looks around at each, not along
// lanes (skills/look-points.asl; navigation, wide tuning 101-160 x 1-2: 98 -> 107 of 120, held out
// 103 -> 106)
lookSpacing(1.0).
// a look point's 60 s are stretched while the robot came nearer it within the last 10 s (look-points.asl;
// navigation, wide tuning 101-160 x 1-2: 108 -> 109 of 120, held out 106 -> 106, classic 143 -> 143)
lookNearing(10000).
// a look point within 0.6 m of a full look around made in the last 120 s gets none (skills/look-skip.asl;
// navigation, wide tuning 101-160 x 1-2: 110 -> 111 of 120, 284 -> 282 deliveries; held out 107 -> 109,
// 289 -> 298)
lookSkip(0.6, 120000).
