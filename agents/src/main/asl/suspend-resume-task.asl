// Experiment 4 with one robot and two agents (not in the thesis: its Chapter 6 wish, "the single
// robot programmed by more agents"): the task agent. It does experiment 4's task (search, pick,
// deliver) with the same skills as suspend-resume.asl, without the recharge: the energy agent
// (suspend-resume-energy.asl) asks it to suspend when the battery runs low and to resume after
// the recharge. The wheels are one agent's at a time (skills/shared-wheels.asl).
// Run: jacabot experiment suspend-resume --agents task,energy

middlewareClass("jacabot.experiments.SuspendResumeMiddleware").

!start.

{ include("skills/shared-wheels.asl") }
{ include("skills/task-agent.asl") }
{ include("skills/initial-phase.asl") }
{ include("skills/suspension.asl") }
{ include("skills/delivery.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
{ include("skills/recovery.asl") }
{ include("skills/progress-watch.asl") }
{ include("skills/sweep.asl") }
{ include("skills/random-walk.asl") }
