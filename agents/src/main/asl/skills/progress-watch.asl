// Skill: progress watch, recovery not in the thesis. The Khepera's middleware compares the GPS
// positions over two windows and signals "stuck" when the wheels turn but the robot stays within
// a few centimetres (wedged) or circles; the task skills say what to do then (their +stuck plans:
// escape, leave the storage area, re-align). Any position (include it anywhere).
// Parameters: ms and metres of the two windows (14 s within 3 cm, 40 s within 12 cm)
stuckWindows(14000, 0.03, 40000, 0.12).
setUpGoal(setUpProgressWatch).

@setUpProgressWatch +!setUpProgressWatch : stuckWindows(T1, R1, T2, R2) <- progressWindows(T1, R1, T2, R2).
