// Team delivery, not in the thesis (its Chapter 6: multi-robot systems): N Kheperas bring the
// arena's red cylinders to one storage area and share one charger. Every robot's agent is this
// program, named as its robot; they coordinate through the team's artifacts (task board, charger
// queue). The team's skills come first: team-storage (one robot at a time at the storage point),
// team-places (where the teammates are), team-way (who gives way to whom), team-follow (a
// following distance on the same way), team-claims (who
// fetches which cylinder), team-charger (the charger by need, one at a time), team-search (each
// robot searches where no one has looked); the other skills
// are experiment 4's. From the world file:
// storagePoint(X, Z), storageRadius(R), charger(X, Z), arena(W, D). From the runner: taskEnd(T), the
// run's end (recharge-trip and team-charger make no trip, book no place, while the battery covers
// the time left).

middlewareClass("jacabot.experiments.SuspendResumeMiddleware").
// recharged, a robot goes on from the charger (recharge-trip): the way back to the point marked
// when the battery went low crossed the arena empty, and could end in the storage area's corner
resumeAtCharger.
// a delivery under way nearer the storage point than the charger ends first (recharge-trip) while the
// battery less 300 J covers the way on to the charger: a trip begun in the storage area left the
// robot believing itself in it, halted and blind, against a wall (team world 2, four robots)
deliverFirst(300).

!start.

{ include("skills/team-storage.asl") }
{ include("skills/storage-exit.asl") }
{ include("skills/team-places.asl") }
{ include("skills/team-way.asl") }
{ include("skills/team-follow.asl") }
{ include("skills/team-claims.asl") }
{ include("skills/team-charger.asl") }
{ include("skills/team-search.asl") }
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
