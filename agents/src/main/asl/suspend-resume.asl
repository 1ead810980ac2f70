// Experiment 4: task suspend/resume (thesis Chapter 4 §4 and Appendix B): the navigation robot
// (experiment 3) and, when the battery runs low, suspension of whatever runs, a trip to the charger
// and back, and resumption (skills/recharge.asl). storagePoint(X, Z), charger(X, Z) and arena(W, D)
// come from the world file (the launcher adds them as initial beliefs; the .mas2j passes them with
// beliefs="..."). The thesis' plans as published: as-published/suspend-resume.asl.

middlewareClass("jacabot.experiments.SuspendResumeMiddleware").
// a waypoint of the sweep is skipped once the robot has come no closer to it by waypointProgress m
// for waypointPatience ms (a fixed 60 s per waypoint left the robot half a minute among boxes in
// front of a waypoint it could not reach, as in gradle run's story; generated worlds: 128 -> 131
// of 150, held out 123 -> 123)
waypointPatience(20000).
waypointProgress(0.1).

!start.

{ include("skills/initial-phase.asl") }
{ include("skills/recharge.asl") }
{ include("skills/delivery.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
{ include("skills/recovery.asl") }
{ include("skills/sweep.asl") }
{ include("skills/random-walk.asl") }

@setUp +!setUp <- !setUpRecovery; !setUpRecharge; !setUpSweep; !setUpDelivery; !setUpFarSight.
