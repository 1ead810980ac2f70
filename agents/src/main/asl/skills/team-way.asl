// Skill: right of way between teammates (thesis Chapter 6, multi-robot coordination; not in the
// thesis). A robot's distance sensors see another robot as an obstacle, and when two robots meet
// both avoid at once, often into each other. Both robots of a pair apply one rule to the places
// on the task board (team-places): when two robots are within wayClearance of each other, the one
// whose name comes later in the alphabet gives way and the other goes on as it was; a robot that
// stands in a queue for its turn (the storage area's, or the charger's near it) is given way by
// everyone. Giving way is
// one atomic manoeuvre (no other plan drives the wheels meanwhile): back off from a teammate ahead,
// or move on away from one behind, for wayTime, then stop and let the skills steer again. A robot
// standing for its turn (halted: the charger, the storage area) or picking does not move for it.
// Parameters:
wayClearance(0.13).   // m between two robots' centres (a Khepera is 5.7 cm wide, its gripper and a
                      // cylinder held reach 9 cm ahead of its centre)
wayTime(600).         // ms of the manoeuvre
waySpeed(40).         // wheel speed of the manoeuvre
wayQueueReach(0.45).  // m from the charger where a robot queued for it stands (team-charger)
// Beliefs: givingWay. Reads: robotAt(A, X, Z), storageQueue(L) (the board), chargerQueue(L) (the
// charger), charger(X, Z) (the world), location, orientation, picking.
// Needs: team-places (the places published), halted (heading, and the skills that extend it).

// the rule both robots follow: the earlier name has the right of way, and a robot standing in a queue
rightOfWay(A) :- .my_name(Me) & A \== Me & (A < Me | standing(A)).
standing(A) :- storageQueue([_ | W]) & .member(A, W).
standing(A) :- chargerQueue([_ | W]) & .member(A, W) & robotAt(A, X, Z) & charger(Cx, Cz) & wayQueueReach(Q)
    & (X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz) < Q * Q.
tooClose(Ax, Az) :- location(X, _, Z) & wayClearance(C) & (Ax - X) * (Ax - X) + (Az - Z) * (Az - Z) < C * C.
aheadOfMe(Ax, Az) :- location(X, _, Z) & orientation(O) & R = O * math.pi / 180
    & (Ax - X) * math.cos(R) + (Az - Z) * math.sin(R) > 0.

@giveWay[atomic]
+robotAt(A, Ax, Az) : rightOfWay(A) & tooClose(Ax, Az) & not givingWay & not halted & not picking & waySpeed(V) & wayTime(T)
    <- +givingWay; .print("Giving way to ", A);
       if (aheadOfMe(Ax, Az)) { setSpeeds(-V, -V) } else { setSpeeds(V, V) };
       .wait(T); stop; -givingWay.
