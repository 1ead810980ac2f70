// Skill: right of way between teammates (thesis Chapter 6, multi-robot coordination; not in the
// thesis). A robot's distance sensors see another robot as an obstacle, and when two robots meet
// both avoid at once, often into each other. Both robots of a pair apply one rule to what the
// team's artifacts show (team-places, the queues): when two robots are within wayClearance of each
// other, the one of lower rank gives way and the other goes on as it was; of equal rank, the one
// whose name comes later gives way. Ranks, highest first: the robot whose turn it is (the head of
// the storage area's queue; the head of the charger's queue near the charger, arriving, charging
// or leaving it), a robot standing in a queue for its turn (waiting near the charger, or for the
// storage area), any other robot. (Tried: a robot that carries a cylinder ranked above one that
// does not; it drove on at travel speed into a searching robot backing off from it, head-on, for
// 2.6 s: held-out world 42, two robots.) (Tried: the robot
// whose turn it is at the storage area ranked as any robot; it then gave way to a robot not
// queued that followed it, and they touched for 29 s, world 6 with four robots.) Giving way is one
// atomic manoeuvre (no other plan drives the wheels meanwhile): a step aside from a teammate ahead
// (a turn away from it, then forward: out of its line), or a move on away from one behind, then
// stop and let the skills steer again; a robot that would push another teammate right
// ahead by moving on steps aside from that one instead. (Backing off from a teammate ahead at 0.02 m/s while it came
// on at 0.05 m/s kept them touching 2-4 s, head-on on the way between storage area and charger.)
// The robot with the right of way, travelling or driving into the storage area, stops a moment
// while a teammate giving way is right ahead of it (wayStop), so that it does not push that
// teammate along (into the storage area's corner: world 6 with four robots), for wayStopLimit at
// most. (Tried: stopping too while it leaves the storage area; worse on worlds 1-8.) A robot
// that waits for its turn or behind a teammate gives way too, then stands again (waiting robots
// that never moved were driven into by the one whose turn had come); one on the charger or in
// the storage area does not move for it; a robot picking does (a cylinder next to a teammate is
// most often the one it carries).
// A robot that starts to wait (for its turn, behind a teammate) stands still: a detour or a
// re-alignment begun on the way is over (!standStill), and a re-alignment ending while it waits
// does not drive it on (the detour's last step cruised a robot waiting at the charger into the
// corner, pushing the teammate on the charger's edge for 20 s: world 3, four robots).
// Parameters:
wayClearance(0.13).   // m between two robots' centres (a Khepera is 5.7 cm wide, its gripper and a
                      // cylinder held reach 9 cm ahead of its centre)
wayTime(600).         // ms of the manoeuvre away from a teammate behind
// wheel speed of that manoeuvre: the speed a teammate behind comes on at, travelling (far-sight's
// travelSpeed). (Moving on at 40 while the one behind came on at 100, the robot giving way was caught
// and pushed: a replay of team world 45, four robots.)
waySpeed(V) :- travelSpeed(V).
asideSpeed(100).      // wheel speed of the step aside from a teammate ahead: a turn away, then forward
asideTurn(450).       // ms of its turn (about 50 degrees)
asideTime(800).       // ms forward after it (4 cm)
wayStop(0.1).         // m: the robot with the right of way stops while a teammate giving way is this near, ahead
wayStopTime(400).     // ms of one such stop
wayStopLimit(3000).   // ms it stops for one teammate at most (then it drives on: its detours go round) ...
wayStopAgain(10000).  // ... and not again for that teammate during this long
wayQueueReach(0.45).  // m from the charger where a robot queued for it stands (team-charger)
// Beliefs: givingWay, stoppedFor(A, Since). Reads: travelSpeed(V) (far-sight), robotAt(A, X, Z), storageQueue(L) (the board),
// chargerQueue(L) (the charger), charger(X, Z) (the world), location, orientation, atCharger,
// insideArea, travelling, delivering, avoiding (delivery, heading). Rules it offers: rightOfWay(A),
// standing(A), aheadOfMe(X, Z), teammateInMyWay(X, Z); the rule waitingTurn, which the skills that make a robot wait
// extend (team-storage, team-follow, team-charger).
// Needs: team-places (the places published, during a manoeuvre too: !waitPublishing), halted (heading, and the skills that extend it).
// Include it before delivery (heading): its plan for !cruise comes first.

// the rule both robots follow (never both give way): the higher rank, else the earlier name
rightOfWay(A) :- .my_name(Me) & A \== Me & wayRank(A, Ra) & wayRank(Me, Rm) & (Ra > Rm | Ra == Rm & A < Me).
wayRank(A, 2) :- turnHolder(A).
wayRank(A, 1) :- not turnHolder(A) & standing(A).
wayRank(A, 0) :- not turnHolder(A) & not standing(A).
turnHolder(A) :- storageQueue([A | _]).
turnHolder(A) :- chargerQueue([A | _]) & inChargerReach(A).
standing(A) :- storageQueue(L) & .member(A, L).
standing(A) :- chargerQueue(L) & .member(A, L) & inChargerReach(A).
inChargerReach(A) :- robotAt(A, X, Z) & charger(Cx, Cz) & wayQueueReach(Q) & (X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz) < Q * Q.
// a robot that only waits may give way (it stands again after); one charging or putting down may not
cannotGiveWay :- halted & not waitingTurn.
cannotGiveWay :- atCharger.
cannotGiveWay :- insideArea.
tooClose(Ax, Az) :- location(X, _, Z) & wayClearance(C) & (Ax - X) * (Ax - X) + (Az - Z) * (Az - Z) < C * C.
aheadOfMe(Ax, Az) :- location(X, _, Z) & orientation(O) & R = O * math.pi / 180
    & (Ax - X) * math.cos(R) + (Az - Z) * math.sin(R) > 0.
// the teammate lies at a greater angle than the heading (turning the wheels (-V, V) puts it aside)
onGreaterAngle(Ax, Az) :- location(X, _, Z) & orientation(O) & R = O * math.pi / 180
    & math.cos(R) * (Az - Z) - math.sin(R) * (Ax - X) > 0.
// a teammate that gives way to this robot, right ahead of it (within 45 degrees of its heading)
givesWayToMe(A) :- .my_name(Me) & A \== Me & wayRank(A, Ra) & wayRank(Me, Rm) & (Rm > Ra | Ra == Rm & Me < A).
rightAhead(Ax, Az) :- location(X, _, Z) & orientation(O) & wayStop(S) & R = O * math.pi / 180
    & D2 = (Ax - X) * (Ax - X) + (Az - Z) * (Az - Z) & D2 < S * S
    & (Ax - X) * math.cos(R) + (Az - Z) * math.sin(R) > 0.7 * math.sqrt(D2).
// driving on its way (not turning, not going round): the wheels it stops it sets again
drivingOn :- travelling & not halted & not avoiding & not givingWay.
drivingOn :- insideArea & delivering & not givingWay.
teammateInMyWay(Bx, Bz) :- robotAt(B, Bx, Bz) & not .my_name(B) & tooClose(Bx, Bz) & aheadOfMe(Bx, Bz).
stopDue(A) :- not stoppedFor(A, _).
stopDue(A) :- stoppedFor(A, T0) & .system_time(T) & wayStopLimit(L) & T - T0 < L.

@stepAside[atomic]
+robotAt(A, Ax, Az) : rightOfWay(A) & tooClose(Ax, Az) & not givingWay & not cannotGiveWay & aheadOfMe(Ax, Az)
    <- +givingWay; .print("Stepping aside for ", A); !sideStep(Ax, Az); -givingWay.
// moving on would push a teammate right ahead: a step aside from that one instead (team world 43,
// four robots: a robot moving on away from the one behind it pushed the one standing ahead for 3 s)
@stepAsideBoxedIn[atomic]
+robotAt(A, Ax, Az) : rightOfWay(A) & tooClose(Ax, Az) & not givingWay & not cannotGiveWay & teammateInMyWay(Bx, Bz)
    <- +givingWay; .print("Stepping aside for ", A, ": a teammate ahead"); !sideStep(Bx, Bz); -givingWay.
// a turn away from the teammate's side at full speed, then forward: out of its line
@sideStep
+!sideStep(X, Z) : asideSpeed(V) & asideTurn(Tt) & asideTime(Ta)
    <- if (onGreaterAngle(X, Z)) { setSpeeds(-V, V) } else { setSpeeds(V, -V) };
       !waitPublishing(Tt); setSpeeds(V, V); !waitPublishing(Ta); stop.
@giveWay[atomic]
+robotAt(A, Ax, Az) : rightOfWay(A) & tooClose(Ax, Az) & not givingWay & not cannotGiveWay & waySpeed(V) & wayTime(T)
    <- +givingWay; .print("Giving way to ", A); setSpeeds(V, V); !waitPublishing(T); stop; -givingWay.

// the robot with the right of way does not push a teammate giving way right ahead of it
@stopForTeammate[atomic]
+robotAt(A, Ax, Az) : drivingOn & givesWayToMe(A) & rightAhead(Ax, Az) & stopDue(A) & wayStopTime(T)
    <- if (not stoppedFor(A, _)) { .system_time(Now); +stoppedFor(A, Now); !!stopAgainLater(A) };
       stop; .wait(T);
       if (drivingOn & not .intend(balance)) { !cruise }.
@stopAgainLater +!stopAgainLater(A) : wayStopAgain(T) <- .wait(T); -stoppedFor(A, _).

// a robot that starts to wait stands still: what was driving it on its way is over
@standStill
+!standStill
    <- .drop_intention(balance); if (.intend(detour(_))) { .drop_intention(detour(_)); -avoiding }; stop.
// a re-alignment that ends while the robot waits (its own, or one left over) does not drive it on
@noCruiseWhileWaiting +!cruise : waitingTurn <- stop.
