// Experiment 3: navigation (thesis Chapter 4 §3), with the Khepera's GPS and compass: the
// cylinder picked (experiment 2) is delivered to the storage point (skills/delivery.asl); a sweep
// of the arena by look points (skills/look-points.asl, skills/sweep.asl) finds the cylinders the
// random walk misses. It is the Appendix B agent without the battery module. storagePoint(X, Z),
// storageRadius(R) and arena(W, D) come from the world file (the launcher adds them as initial
// beliefs; the .mas2j passes them with beliefs="..."): no coordinate is written here. The thesis'
// plans as published: as-published/navigation.asl.

middlewareClass("jacabot.experiments.NavigationMiddleware").
// turns on the spot at half speed but for the last 15 degrees (heading.asl; tidy-up's): the listing's
// 25/-10 turn took 9 s a half turn, and every sweep step and re-alignment began with one
quickTurns.
// the sweep heads for look points 1 m apart and looks around at each, not along lanes, the look
// points' time stretched while the robot comes nearer, none near a recent look around
// (skills/look-search.asl, shared with suspend/resume)
{ include("skills/look-search.asl") }
// a wall is followed the way the robot came (skills/trail-side.asl): a trail point every 0.1 m (wide
// tuning 101-160 x 1-2: 109 -> 110 of 120, 273 -> 284 deliveries; held out 106 -> 107; classic 143 -> 145)
trailStep(0.1).
// the look around after a cylinder fell on the way comes whole even when an avoidance cuts it short
// (skills/search-memory.asl)
fallLookKept.

!start.

{ include("skills/initial-phase.asl") }
{ include("skills/trail-side.asl") }
{ include("skills/way-round.asl") }
// the sweep's way to a waypoint goes round the storage area (a lane across it led to and fro there)
{ include("skills/storage-bypass.asl") }
{ include("skills/delivery.asl") }
// a cylinder knocked out of the gripper by the storage area is turned to and fetched (picking is off there otherwise)
{ include("skills/knock-fetch.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
// cylinders seen and not gone for are remembered and looked for first; the sweep goes on along the
// lanes not yet driven, from the corner nearest the robot
{ include("skills/search-memory.asl") }
{ include("skills/recovery.asl") }
{ include("skills/progress-watch.asl") }
{ include("skills/look-skip.asl") }
{ include("skills/look-points.asl") }
{ include("skills/sweep.asl") }
{ include("skills/random-walk.asl") }
