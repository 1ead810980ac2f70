// Experiment 2: red-cylinder picking (thesis Chapter 4 §2), with the Khepera: random motion and
// obstacle avoidance, and a red cylinder seen is picked up (skills/picking.asl), or gone to when
// seen far off (skills/far-sight.asl). This agent has no map: after searchAfter ms without a
// cylinder its random moves give way to long straight legs in random directions (its own plan).
// The thesis' plans as published: as-published/object-picking.asl.

middlewareClass("jacabot.experiments.ObjectPickingMiddleware").
searchAfter(60000).
// the random walk's straight legs at travelSpeed (twice the ground in big arenas); once a
// cylinder is held, the thesis' 50 (at 100 the battery, 1000 J, is empty after about 8 minutes)
legSpeed(50) :- picked(true).
legSpeed(V) :- not picked(true) & travelSpeed(V).

!start.

{ include("skills/initial-phase.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
{ include("skills/recovery.asl") }
{ include("skills/progress-watch.asl") }

setUpGoal(startSearchClock).
@startSearchClock +!startSearchClock <- .system_time(Now); +lastFound(Now).

// no cylinder for a while: long straight legs in random directions
@searchLeg
+!move(N) : searchAfter(S) & lastFound(T0) & .system_time(T) & T - T0 > S & not picked(true) & maxSpeed(M)
    <- .random(R); setSpeeds(M / 2, -M / 2); .wait(R * 3000); ?legSpeed(V); setSpeeds(V, V); .wait(15000).

{ include("skills/random-walk.asl") }

// the cylinder held, the robot walks on with it (the thesis has no delivery in this experiment)
@carryPicked +!go_ahead : picked(true) <- println("Cylinder picked up"); -picking; .system_time(T); -+lastFound(T); forward.

// the carried cylinder has fallen: the thesis stops for good ("stopAcquire; stop"); the robot
// drops everything, lets the cylinder go and looks for a cylinder again
@fallCarried[atomic]
+fallen
    <- .drop_all_desires; .print("Cylinder has fallen. Anybody retrieve it");
       stop; -picking; -avoiding; -+reachCylinder(false); open_grip; arm_up; !!moving.

// no progress though the wheels turn (the middleware's "stuck"): escape
@stuckWhileBusy +stuck : picking | picked(true) | avoiding.
@stuckWalking +stuck <- println("No progress: escaping"); +avoiding; .succeed_goal(move(_)); stop; !escape; -avoiding.
