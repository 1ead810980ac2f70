// Experiment 4: task suspend/resume (thesis Chapter 4 §4 and Appendix B): the navigation robot
// (experiment 3) and, when the battery runs low, suspension of whatever runs, a trip to the charger
// and back, and resumption (skills/recharge.asl). storagePoint(X, Z), charger(X, Z) and arena(W, D)
// come from the world file (the launcher adds them as initial beliefs; the .mas2j passes them with
// beliefs="..."). The thesis' plans as published: as-published/suspend-resume.asl.

middlewareClass("jacabot.experiments.SuspendResumeMiddleware").

// the look around after a cylinder fell on the way comes whole even when an avoidance cuts it short
// (skills/search-memory.asl; as navigation's: wide tuning 101-160 x 1-2 110 -> 111 of 120, x 3-4
// 109 -> 110, held out 241-300 x 1-2 113 -> 113 (244 -> 245 deliveries), classic 1-50 x 1-3 150 -> 150)
fallLookKept.

!start.

// the sweep keeps its route's point up to 6 s (until reached or an obstacle met: route.asl), where
// re-planning at every step swung it left and right near its waypoint
routeHold(6000).
// turns on the spot at half speed but for the last 15 degrees (heading's quickTurnAt), small turns on
// the way in an arc (arc-turn.asl), obstacles kept on the route map the whole run and a wall's face
// taken to go on past its seen end (route.asl: a doorway driven through is taken first): the trips
// and the sweep stop and turn less (held out, wide 241-300 × 1, 2: 104 -> 113 of 120; tuning 101 -> 109,
// 105 with the turns alone: docs/comparison-wide.md)
routeMemory(600000).
wallGuess(1.0).
// the guess's first 0.15 m past the seen end firm, ended by a side sensor seeing the floor open: the
// trips go along a wall at full speed, where they crept at 1-2 cm/s into its unseen part (wide tuning
// 101-160: the first trip to the charger sooner in 30 runs, later in 5: docs/comparison-wide.md)
wallFirm(0.15).
quickTurns.
// the way back's progress judged along the route map too, not only in a straight line (recharge-trip's
// @reachMarkedAlongRoute: docs/comparison-wide.md)
markedByRoute.
// the sweep heads for look points at most 1 m apart and looks around at each, not along lanes from wall
// to wall (3-4 m each in the wide arenas: the room the robot began in took the run), navigation's
// parameters (skills/look-search.asl, look-points.asl, look-skip.asl; wide tuning 101-160 x 1-2: 111 -> 115
// of 120, x 3-4: 113 -> 116, held out 241-300 x 1-2: 112 -> 114; docs/comparison-wide.md)
{ include("skills/look-search.asl") }
{ include("skills/initial-phase.asl") }
// the way to the charger and the sweep's waypoints through the robot's own map, the way back along
// its trail (with the hold and @rechargeOutOfArea, held out: wide worlds 131-160 15 -> 23 of 30,
// classic 31-40 with seeds 1-3 28 -> 30 of 30: docs/comparison-wide.md)
{ include("skills/way-back.asl") }
// the sweep's way to a waypoint goes round the storage area (before route.asl: its plans match
// first), and cylinders seen and not gone for are looked for first (search-memory), as in navigation:
// held out, wide 241-300 seed 1 49 -> 51 of 60, deliveries 84 -> 103 (docs/comparison-wide.md)
{ include("skills/storage-bypass.asl") }
{ include("skills/route.asl") }
// a low battery in the storage area with the cylinder waits until it is put down and the robot is
// out (lowBattery comes again at every control step): a trip begun there left it halted
// (insideArea), blind, with the cylinder (docs/comparison-wide.md)
@rechargeOutOfArea +lowBattery : insideArea & ~delivered & not charging.
// a cylinder knocked out of the gripper on the trip ends the trip no more (before recharge.asl)
{ include("skills/trip-after-fall.asl") }
{ include("skills/recharge.asl") }
// small turns on the way in an arc, not on the spot (before delivery: heading's turns come after)
{ include("skills/arc-turn.asl") }
// no progress in the storage area after the put-down: out towards the arena's centre
{ include("skills/storage-exit.asl") }
{ include("skills/delivery.asl") }
// a cylinder knocked out of the gripper by the storage area is turned to and fetched (picking is off there otherwise)
{ include("skills/knock-fetch.asl") }
{ include("skills/avoidance.asl") }
{ include("skills/picking.asl") }
{ include("skills/far-sight.asl") }
// cylinders seen and not gone for are looked for first; the sweep goes on with the look points left
{ include("skills/search-memory.asl") }
{ include("skills/look-skip.asl") }
{ include("skills/look-points.asl") }
{ include("skills/recovery.asl") }
{ include("skills/progress-watch.asl") }
{ include("skills/sweep.asl") }
{ include("skills/random-walk.asl") }
