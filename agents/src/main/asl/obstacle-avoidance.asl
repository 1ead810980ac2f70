// Experiment 1: obstacle avoidance (thesis Chapter 4 §1), with the two-sensor MyBot: random
// motion, and an obstacle avoided by turning away from its side (skills/coverage.asl, with the
// recovery of skills/recovery.asl). The thesis' plans as published: as-published/obstacle-avoidance.asl.
// arena(W, D) comes from the world file (the launcher adds it as an initial belief).

middlewareClass("jacabot.experiments.ObstacleAvoidanceMiddleware").
// skills/floor-drive.asl (the door drive, form F6): after 30 s with under 3 new cells, in arenas of 4 m2 or
// more, a drive of up to 30 s to uncrossed floor 1 m or more away along crossed floor, the marks in
// crossed cells forgotten for it (a doorway crossed once stays open)
floorDrive(30000, 3, 30000) :- arena(W, D) & W * D >= 4.
doorOpen.
regionFar(10).

!start.

{ include("skills/initial-phase.asl") }
{ include("skills/floor-drive.asl") }
{ include("skills/coverage.asl") }
{ include("skills/recovery.asl") }
