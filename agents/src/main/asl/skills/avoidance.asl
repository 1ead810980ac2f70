// Skill: obstacle avoidance of the Khepera (thesis Chapter 4 §1.1-§1.2): the middleware's
// obstacle(true) (front) and lateralObstacle(S) (a side) make the robot back off and turn away
// from the obstacle's side until it clears; the coordination belief "avoiding" suspends random
// motion meanwhile.
// Reads: maxSpeed(M); delta(D) (the middleware's left-right difference); the states of the skills
// it stands aside for: picking, reachCylinder(true), picked(true) (picking), travelling (delivery,
// recharge: they go round obstacles their own way), homing(_) (far sight), avoidingInMove (recovery).
// Needs: !clear (recovery); !goRound (far sight) when homing.
// Include it after delivery and recharge (their obstacle plans come first) and before picking.
// Deviations from the listing: the obstacle plans end the random motion that runs
// (.succeed_goal(move(_))): "avoiding" only suspends the next move, so a move plan already in its
// .wait would later send "forward" in the middle of the avoiding turn; the thesis'
// ".wait("+obstacle(false)")" is !clear, a bounded wait (recovery, not in the thesis).

@avoidObstacle
+obstacle(true) : delta(D) & not avoiding & not picking & not reachCylinder(true)
    <- +avoiding; .succeed_goal(move(_)); stop; .system_time(T); -+lastAvoid(T); .wait(50); !avoid(D).

// Recovery, not in the thesis: a lateral obstacle is avoided as a front one, one avoidance at a
// time (the listing's concurrent !avoid waited for an obstacle(false) that never came).
@avoidLateral
+lateralObstacle(S) : not avoiding & not picking & not reachCylinder(true) & not picked(true) & not travelling
    <- +avoiding; .succeed_goal(move(_)); stop; if (S == "left") { !avoid(-1) } else { !avoid(1) }.

@avoidFront +!avoid(0) <- backward; turnAround; !clear; -avoiding; !afterAvoid.
@avoidRight +!avoid(D) : D > 0 & maxSpeed(M) <- backward; setSpeeds(M / 2, -M / 2); !clear; -avoiding; !afterAvoid.
@avoidLeft +!avoid(_) : maxSpeed(M) <- backward; setSpeeds(-M / 2, M / 2); !clear; -avoiding; !afterAvoid.
// homing on a far cylinder when the obstacle came: go round it first (far sight)
@afterAvoidGoRound +!afterAvoid : homing(_) & not travelling <- !goRound.
@afterAvoid +!afterAvoid.

// an avoidance inside the move (recovery's @moveAvoidStill) is cut off with it when picking ends
// the move for a cylinder (.succeed_goal(move(_))), before it takes "avoiding" back, and every
// later move waited for "avoiding" to go (wide worlds: robots stood still to the end of the run):
// the next move takes it back. The reach goes on alone: picking comes before avoidance
@moveAfterCutOff +!move(N) : avoidingInMove <- -avoidingInMove; -avoiding; !move(N).
@moveWhileAvoiding +!move(N) : avoiding <- .wait("-avoiding"); !move(N).
