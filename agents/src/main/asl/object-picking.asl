// Experiment 2: red-cylinder picking (thesis Chapter 4 §2), with the Khepera: random motion and
// obstacle avoidance, and a red cylinder seen is picked up (skills/picking.asl), or gone to when
// seen far off (skills/far-sight.asl). With the Khepera's GPS and compass (location, orientation)
// a sweep of the arena by look points (skills/look-points.asl, skills/sweep.asl: navigation's
// search) finds the cylinders the random walk misses. arena(W, D) comes from the world file (the
// launcher adds it as an initial belief).
// The thesis' plans as published: as-published/object-picking.asl.

middlewareClass("jacabot.experiments.ObjectPickingMiddleware").
// the random walk's straight legs at travelSpeed (twice the ground in big arenas); once a
// cylinder is held, the thesis' 50 (at 100 the battery, 1000 J, is empty after about 8 minutes)
legSpeed(50) :- picked(true).
legSpeed(V) :- not picked(true) & travelSpeed(V).
// quick turns on the spot (heading.asl), as navigation's
quickTurns.
// the sweep heads for look points at most this far apart (m) and looks around at each, not along
// lanes (skills/look-points.asl, navigation's search at navigation's 1.0 m: fewer points leave the
// battery, no charger here, for the room beyond the inner wall), and a following towards one begun
// alongside the wall turns to it first (way-round.asl): wide tuning 101-160 x 1-2 115 -> 119 of 120
lookSpacing(1.5).
turnToWall.

!start.

{ include("skills/initial-phase.asl") }
// the GPS and compass as percepts (location, orientation): the sweep heads for its waypoints
setUpGoal(setUpLocation).
@setUpLocation +!setUpLocation <- publishLocation.

{ include("skills/way-round.asl") }
// the sweep's heading for its waypoints (no trip to a target point here)
{ include("skills/heading.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
{ include("skills/search-memory.asl") }
{ include("skills/recovery.asl") }
{ include("skills/progress-watch.asl") }

// the cylinder held, the robot walks on with it (the thesis has no delivery in this experiment)
@carryPicked +!go_ahead : picked(true) <- println("Cylinder picked up"); -picking; !found; forward.

// the carried cylinder has fallen: the thesis stops for good ("stopAcquire; stop"); the robot
// drops everything, lets the cylinder go and looks for a cylinder again (the sweep's clock too)
@fallCarried[atomic]
+fallen
    <- .drop_all_desires; .print("Cylinder has fallen. Anybody retrieve it");
       stop; -picking; -avoiding; -+reachCylinder(false); open_grip; arm_up; !!searchClock; !!moving.

// no progress while picking or carrying, or avoiding already: nothing more (the sweep's
// +stuck plan escapes otherwise)
@stuckWhileBusy +stuck : picking | picked(true) | avoiding.

{ include("skills/look-points.asl") }
{ include("skills/sweep.asl") }
{ include("skills/random-walk.asl") }
