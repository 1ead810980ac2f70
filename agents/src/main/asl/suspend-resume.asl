// Experiment 4: task suspend/resume (thesis Chapter 4 §4 and Appendix B): the navigation robot
// (experiment 3) and, when the battery runs low, suspension of whatever runs, a trip to the charger
// and back, and resumption (skills/recharge.asl). storagePoint(X, Z), charger(X, Z) and arena(W, D)
// come from the world file (the launcher adds them as initial beliefs; the .mas2j passes them with
// beliefs="..."). The thesis' plans as published: as-published/suspend-resume.asl.

middlewareClass("jacabot.experiments.SuspendResumeMiddleware").

!start.

{ include("skills/initial-phase.asl") }
{ include("skills/recharge.asl") }
{ include("skills/delivery.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
{ include("skills/recovery.asl") }
{ include("skills/progress-watch.asl") }
{ include("skills/sweep.asl") }
{ include("skills/random-walk.asl") }
