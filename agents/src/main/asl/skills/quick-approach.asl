// Skill: the quick near approach, not in the thesis: the last farApproach (0.45 m) to a cylinder
// seen is driven at this wheel speed, not far sight's approachSpeed (40: 2 cm/s, one 0.45 m away
// took 22 s). It is a parameter only: far-sight.asl's nearSpeed reads it. An agent that includes
// it (tidy-up, navigation) includes it among its parameters.
// tidy-up, tuning 171-210 x 1..3: 113 -> 114 of 120, 98 runs sooner, 13 later (mean -41 s);
// navigation, wide tuning 101-160 x 1-2: 112 -> 113 of 120, x 3-4: 112 -> 114
quickApproach(85).
