// Team delivery, not in the thesis (its Chapter 6: multi-robot systems): N Kheperas bring the
// arena's red cylinders to one storage area and share one charger. Every robot's agent is this
// program, named as its robot; they coordinate through the team's artifacts (task board, charger
// queue: skills/team-claims.asl). The other skills are experiment 4's. From the world file:
// storagePoint(X, Z), storageRadius(R), charger(X, Z), arena(W, D).

middlewareClass("jacabot.experiments.SuspendResumeMiddleware").

!start.

{ include("skills/team-claims.asl") }
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
