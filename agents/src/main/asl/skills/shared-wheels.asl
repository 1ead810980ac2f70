// Skill: one robot, several agents (not in the thesis: its Chapter 6 wish, "the single robot
// programmed by more agents"). The middleware artifact lends the wheels to one agent at a time
// (acquireWheels, releaseWheels; the observable property wheels(Holder), Holder an agent or free)
// and refuses the wheel commands of the others (error wheels_held_by(Holder)). While the wheels are
// not this agent's (wheelsNotMine), the percepts that would make it move the robot are left alone
// and its steering stops (halted): its plans do not even try. An agent extends wheelsNotMine with
// its own clauses (energy-agent.asl: not charging).
// Include it FIRST: these plans come before every other skill's for the same events.

wheelsNotMine :- wheels(A) & not .my_name(A).
halted :- wheelsNotMine.

@obstacleNotMine +obstacle(true) : wheelsNotMine.
@lateralObstacleNotMine +lateralObstacle(_) : wheelsNotMine.
@stuckNotMine +stuck : wheelsNotMine.
@sightedNotMine +cylinderSighted(_, _) : wheelsNotMine.
@detectedNotMine +cylinderDetected : wheelsNotMine.
@cylinderLeftNotMine +cylinderLeft : wheelsNotMine.
@cylinderRightNotMine +cylinderRight : wheelsNotMine.
@cylinderBeyondNotMine +cylinderBeyond : wheelsNotMine.
@noAccessNotMine +noAccess : wheelsNotMine.
@targetReachedNotMine +targetReached : wheelsNotMine.
