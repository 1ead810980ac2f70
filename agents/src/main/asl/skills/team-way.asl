// Skill: right of way between teammates (thesis Chapter 6, multi-robot coordination; not in the
// thesis). A robot's distance sensors see another robot as an obstacle, and when two robots meet
// both avoid at once, often into each other. Both robots of a pair apply one rule to the places
// on the task board (team-places): when two robots are within wayClearance of each other, the one
// whose name comes later in the alphabet gives way and the other goes on as it was; but a robot
// that is in a queue for its turn (the storage area's, or the charger's and near it: waiting, or on
// the charger) is given way by every robot that is not. (Tried: the robot whose turn it is at the
// storage area not counted as standing; it then gave way to a robot not queued that followed it,
// and they touched for 29 s, world 6 with four robots.) Giving way is
// one atomic manoeuvre (no other plan drives the wheels meanwhile): back off from a teammate ahead,
// or move on away from one behind, for wayTime, then stop and let the skills steer again. A robot
// standing for its turn (halted: the charger, the storage area) does not move for it; a robot
// picking does (a cylinder next to a teammate is most often the one it carries).
// Parameters:
wayClearance(0.13).   // m between two robots' centres (a Khepera is 5.7 cm wide, its gripper and a
                      // cylinder held reach 9 cm ahead of its centre)
wayTime(600).         // ms of the manoeuvre
waySpeed(40).         // wheel speed of the manoeuvre
wayQueueReach(0.45).  // m from the charger where a robot queued for it stands (team-charger)
// Beliefs: givingWay. Reads: robotAt(A, X, Z), storageQueue(L) (the board), chargerQueue(L) (the
// charger), charger(X, Z) (the world), location, orientation.
// Needs: team-places (the places published), halted (heading, and the skills that extend it).

// the rule both robots follow (never both give way): a robot in a queue before one that is not,
// else the earlier name
rightOfWay(A) :- .my_name(Me) & A \== Me & standing(A) & not standing(Me).
rightOfWay(A) :- .my_name(Me) & A \== Me & A < Me & (standing(A) | not standing(Me)).
standing(A) :- storageQueue(L) & .member(A, L).
standing(A) :- chargerQueue(L) & .member(A, L) & robotAt(A, X, Z) & charger(Cx, Cz) & wayQueueReach(Q)
    & (X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz) < Q * Q.
tooClose(Ax, Az) :- location(X, _, Z) & wayClearance(C) & (Ax - X) * (Ax - X) + (Az - Z) * (Az - Z) < C * C.
aheadOfMe(Ax, Az) :- location(X, _, Z) & orientation(O) & R = O * math.pi / 180
    & (Ax - X) * math.cos(R) + (Az - Z) * math.sin(R) > 0.

@giveWay[atomic]
+robotAt(A, Ax, Az) : rightOfWay(A) & tooClose(Ax, Az) & not givingWay & not halted & waySpeed(V) & wayTime(T)
    <- +givingWay; .print("Giving way to ", A);
       if (aheadOfMe(Ax, Az)) { setSpeeds(-V, -V) } else { setSpeeds(V, V) };
       .wait(T); stop; -givingWay.
