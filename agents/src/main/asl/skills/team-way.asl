// Skill: giving way to a teammate (thesis Chapter 6, multi-robot coordination; not in the thesis).
// Two robots that meet on their ways see each other only as obstacles, and two robots avoiding
// each other at once turned into each other and pushed. When a teammate's published place
// (team-places) is within wayClearance, one of the two stops a moment and lets the other pass: a
// robot on an errand (a cylinder to deliver, a trip to the charger) never gives way, the others
// give way to it; between two robots without an errand, the one whose name comes later gives way.
// A robot gives way to one teammate once per giveWayAgain at most (the other may be standing:
// picking, waiting its turn), so that it never stands for long.
// Parameters:
wayClearance(0.2).     // m between two robots' places under which one gives way
giveWayFor(1500).      // ms it stands still
giveWayAgain(6000).    // ms before it gives way to the same teammate again
// Beliefs: givingWay, gaveWay(Agent, T). Rules it extends: halted.
// Reads: robotAt(A, X, Z) (the board), location(X, Y, Z); delivering, charging, picking,
// insideArea, waitingStorage, waitingCharger, storageTurnMine (other skills); targetPoint,
// travelling (delivery, recharge).
// Needs: heading (computeGap, balance). Include it among the team's skills, before far-sight,
// avoidance, heading and the motion skills: its plans for sightings, obstacles and moves while
// giving way come first.

halted :- givingWay.
onTheWay :- delivering | charging | picking | picked(true) | insideArea | waitingStorage | waitingCharger | storageTurnMine.
mayGiveWayTo(A) :- not onTheWay & .my_name(Me) & Me > A.

@giveWay
+robotAt(A, Ax, Az) : not givingWay & not .my_name(A) & location(X, _, Z) & wayClearance(D)
                     & (X - Ax) * (X - Ax) + (Z - Az) * (Z - Az) < D * D & mayGiveWayTo(A)
                     & .system_time(T) & giveWayAgain(G) & not (gaveWay(A, T0) & T - T0 < G)
    <- -gaveWay(A, _); +gaveWay(A, T); !!giveWay(A).

@giveWayNow
+!giveWay(A) : giveWayFor(W) <- +givingWay; stop; .print("Giving way to ", A); .wait(W); -givingWay; !resumeWay.
@giveWayDropped -!giveWay(_) <- -givingWay.
@resumeTravel +!resumeWay : travelling & targetPoint(_, _) <- !computeGap; !balance.
@resumeWander +!resumeWay <- .succeed_goal(move(_)).

// while giving way the robot stands: nothing that would move it is acted on
@sightedWhileGivingWay +cylinderSighted(_, _) : givingWay.
@obstacleWhileGivingWay +obstacle(true) : givingWay.
@lateralWhileGivingWay +lateralObstacle(_) : givingWay.
@stuckWhileGivingWay +stuck : givingWay.
@moveWhileGivingWay +!move(N) : givingWay <- .wait({-givingWay}); !move(N).
