// Experiment 1: obstacle avoidance (thesis Chapter 4 §1), with the two-sensor MyBot: random
// motion, and an obstacle avoided by turning away from its side (skills/coverage.asl, with the
// recovery of skills/recovery.asl). The thesis' plans as published: as-published/obstacle-avoidance.asl.
// arena(W, D) comes from the world file (the launcher adds it as an initial belief).

middlewareClass("jacabot.experiments.ObstacleAvoidanceMiddleware").

!start.

{ include("skills/initial-phase.asl") }
{ include("skills/coverage.asl") }
{ include("skills/recovery.asl") }
