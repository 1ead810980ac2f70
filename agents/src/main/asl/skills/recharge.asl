// Skill: recharge with suspend/resume (thesis Chapter 4 §4.1 and Appendix B), one agent doing
// both: when the battery runs low whatever runs is suspended (the coordination belief
// "charging", suspension.asl), the robot goes to the charger and back (recharge-trip.asl), and the
// suspended task resumes (-charging). The same two skills serve a robot split between a task agent
// and an energy agent (task-agent.asl, energy-agent.asl).
// Include it FIRST among the skills (suspension.asl's plans come before the task's).

{ include("suspension.asl") }
{ include("recharge-trip.asl") }

// the task is this agent's own: "charging" suspends it; back at the marked point the storage point
// is the target again, the marked orientation restored, and the task resumes
@suspendInPlace +!suspendTask.
@resumeInPlace +!resumeTask(O) <- !restoreTarget; !restoreOrientation(O); -charging.
