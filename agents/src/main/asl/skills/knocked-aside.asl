// Skill: a cylinder knocked out of the gripper is turned to, not avoided, not in the thesis. It lies
// beside the robot (search-memory's lostBeside), and the first distance sensor that shows it after
// the knock says on which side: the robot turns on the spot towards it until the gripper's sensor shows it
// (avoidance turned the robot away from it, again and again, and the sweep drove off: tidy-up world
// 204 × 2, found again 138 s later).
// Parameters:
knockedAside(4500).   // ms after the knock that an obstacle met is taken for the cylinder
knockedTurn(14000).   // ms the turn lasts at most: a full turn at a quarter speed (the side sensed first
                      // may be a box's, world 183 × 2: the cylinder came round after three quarters)
knockedApproach(500, 3000). // ms the turn goes on once the cylinder is ahead (about 13 degrees), and the
                      // approach at a fifth of full speed lasts at most (the central sensor reads it
                      // at about 450 from the knock's 6 cm, 480 to be picked)
// Reads: lostBeside (search-memory's, added when a delivery ends outside the storage area); picking,
// reachCylinder (picking); cylinderLeft, cylinderRight, cylinderBeyond, maxSpeed(M), delta(D) (the middleware's).
// Beliefs: knockedAt(T), turningToKnocked, knockedAhead; avoiding (avoidance's: every move, avoidance and far sight
// wait meanwhile).
// Needs: search-memory (@backOffFirst), avoidance, picking. Include it before avoidance and picking (their
// obstacle and lateral cylinder plans come after).

@knockedBeside +lostBeside <- .system_time(T); -+knockedAt(T).
justKnocked :- knockedAt(T0) & knockedAside(A) & .system_time(T) & T - T0 < A & not avoiding & not picking & not reachCylinder(true).
// towards the side that shows it: the left sensor looks 90 degrees left, and a positive delta (left less right)
// is an obstacle ahead on the left; turnToKnocked(V) turns right for a positive V
@knockedLateral +lateralObstacle(S) : justKnocked & maxSpeed(M)
    <- if (S == "left") { !turnToKnocked(-M / 4) } else { !turnToKnocked(M / 4) }.
@knockedFront +obstacle(true) : justKnocked & maxSpeed(M) & delta(D)
    <- if (D > 0) { !turnToKnocked(-M / 4) } else { !turnToKnocked(M / 4) }.
@turnToKnocked
+!turnToKnocked(V) : knockedTurn(W)
    <- -knockedAt(_); +avoiding; +turningToKnocked; .succeed_goal(move(_)); setSpeeds(V, -V);
       .wait(picking | knockedAhead, W); !approachKnocked; -turningToKnocked; -avoiding.
// the turn goes on until the camera's centre shows the cylinder, a little further (its centre lies
// beyond the first red), then a slow approach until picking's detection takes it: picking's lateral
// reach turned on one wheel and approached at once, and the cylinder, 2 cm from the robot's side,
// was pushed along it (world 183 × 2: pushed 5 cm, lost, found again 200 s later); not in the thesis.
// Something not red right ahead (obstacle(true): a box the cylinder fell against) ends it
@knockedSeenLeft +cylinderLeft : turningToKnocked.
@knockedSeenRight +cylinderRight : turningToKnocked.
@knockedSeenAhead +cylinderBeyond : turningToKnocked <- +knockedAhead.
@approachKnocked
+!approachKnocked : knockedAhead & maxSpeed(M) & knockedApproach(C, A)
    <- -knockedAhead; .wait(C);
       if (not picking & not obstacle(true)) { setSpeeds(M / 5, M / 5); .wait(picking | obstacle(true), A) };
       if (not picking) { stop }.
@approachKnockedNot +!approachKnocked.
// not seen in time: on with the search
@turnToKnockedEnd -!turnToKnocked(_) : not picking <- -turningToKnocked; -knockedAhead; stop; -avoiding.
@turnToKnockedPicking -!turnToKnocked(_) <- -turningToKnocked; -knockedAhead; -avoiding.
