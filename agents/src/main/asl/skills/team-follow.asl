// Skill: a following distance between teammates on the same way (thesis Chapter 6, multi-robot
// coordination; not in the thesis). Robots bringing cylinders to the one storage point meet on the
// way there, side by side or one behind the other, and team-way's back-off, made for robots that
// meet head-on, does not part robots going the same way. A robot bringing a cylinder that has a
// teammate within followDistance, ahead of it and nearer the storage point than it is, stops and
// waits until that teammate is no longer so; the one ahead goes on. Not on the way to the charger:
// there the charger's queue orders the robots, and a robot whose turn it is stopped behind the
// ones waiting near the charger (tried: turns lost, waits of minutes). Both robots read the same places (team-places), and of two robots the nearer one never
// waits for the other, so they never both wait. A wait lasts followTime at most, or
// followTimeStanding if the one ahead stands in a queue (team-way's standing: it waits for its
// turn, so will this one); then that teammate is not waited for during followAgain (avoidance and
// detours take over).
// Parameters:
followDistance(0.25).  // m between two robots' centres (a robot and the cylinder it holds reach 9 cm)
followTime(5000).      // ms a robot waits behind a teammate that does not stand in a queue
followTimeStanding(30000). // ms it waits behind one that does
followAgain(8000).     // ms during which a teammate waited for that long is not waited for again
followPoll(200).       // ms between two looks at the places while waiting
// Beliefs: following(A), followedOut(A). Rules it extends: halted, waitingTurn. Rules it offers: followBehind(A).
// Reads: robotAt(A, X, Z) (the board), targetPoint(X, Z), delivering, onErrand, avoiding, givingWay,
// waitingStorage, storageTurnMine, location, orientation.
// Needs: team-places (the places), team-way (aheadOfMe, standing, !standStill), heading (computeGap, balance,
// steer). Include it after team-way (a teammate too close is given way first) and before heading:
// its plans for obstacles while following come first.

halted :- following(_).
waitingTurn :- following(_).
forgetOnFall(following(_)).

// a teammate nearer the target, ahead, too close; the one with the storage turn drives on
followBehind(A) :- delivering & not onErrand & not storageTurnMine & targetPoint(Tx, Tz) & location(X, _, Z)
    & robotAt(A, Ax, Az) & not .my_name(A) & not followedOut(A) & followDistance(D)
    & (Ax - X) * (Ax - X) + (Az - Z) * (Az - Z) < D * D
    & (Ax - Tx) * (Ax - Tx) + (Az - Tz) * (Az - Tz) < (X - Tx) * (X - Tx) + (Z - Tz) * (Z - Tz)
    & aheadOfMe(Ax, Az).

@followTeammate[atomic]
+robotAt(_, _, _) : not halted & not avoiding & not givingWay & not following(_) & followBehind(A)
    <- +following(A); !standStill; .print("Keeping my distance behind ", A); !!followWait(A, 0).

@followEndsOffTheWay +!followWait(A, _) : not delivering | onErrand | waitingStorage <- -following(A).
@followEnds +!followWait(A, _) : not followBehind(A) <- -following(A); !followResume.
@followGivesUp
+!followWait(A, T) : followTime(L) & T >= L & (not standing(A) | followTimeStanding(Ls) & T >= Ls)
    <- +followedOut(A); -following(A); !!followForget(A); !followResume.
@followWaits +!followWait(A, T) : followPoll(P) <- .wait(P); !followWait(A, T + P).

@followResume +!followResume <- !computeGap; !balance; if (not .intend(steer)) { !!steer }.
@followForget +!followForget(A) : followAgain(T) <- .wait(T); -followedOut(A).

// while waiting behind a teammate the robot stands still: that teammate is an obstacle, and no
// progress is no reason to escape
@obstacleWhileFollowing +obstacle(true) : following(_).
@lateralWhileFollowing +lateralObstacle(_) : following(_).
@stuckWhileFollowing +stuck : following(_).
