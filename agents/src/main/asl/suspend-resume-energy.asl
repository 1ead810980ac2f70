// Experiment 4 with one robot and two agents (not in the thesis: its Chapter 6 wish): the energy
// agent. It watches the battery; when it runs low it suspends the task agent (named below), takes
// the wheels, drives to the charger, waits for the charge, comes back to the marked point and
// hands the wheels and the task back. Between recharges it never moves the robot.
// Run: jacabot experiment suspend-resume --agents task,energy

middlewareClass("jacabot.experiments.SuspendResumeMiddleware").
taskAgent(task).

!start.

{ include("skills/shared-wheels.asl") }
{ include("skills/energy-agent.asl") }
{ include("skills/initial-phase.asl") }
{ include("skills/recharge-trip.asl") }
{ include("skills/heading.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/recovery.asl") }
