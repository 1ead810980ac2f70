// Skill: the team's share of the sweep (thesis Chapter 6, multi-robot coordination; not in the
// thesis). Every robot sweeps the arena along the same lanes (sweep), and each began at the same
// first waypoint: robots of a team that had found no cylinder for a while drove to one corner and
// along the same lanes, looking where a teammate had just looked (team worlds 1 and 4, four robots:
// a third of the robots' time went to sweeping). A robot of a team starts its sweep at its own
// share of the lanes: the waypoints turned by its rank among the teammates (by name) times the
// lanes per robot, and a robot's next search goes on along the lanes it has not yet driven
// (sweep's resumeSweep) instead of starting again where every robot starts. A robot alone, or a
// robot that sees no teammate on the board, sweeps as one robot does.
// Beliefs: sweepShared. Reads: sweep(L) (sweep), robotAt(A, X, Z) (team-places).
// Rules it uses: queuedAhead(L, Me, K) (team-charger: Me's place in a list).
// Needs: sweep (!nextWaypoint, resumeSweep), team-places. Include it before sweep: its plan for
// !nextWaypoint comes first.

resumeSweep.

// this robot's rank K (from 0) among the N robots that publish their places, by name
sweepRank(K, N) :- .my_name(Me) & .findall(A, robotAt(A, _, _), As) & .sort(As, S) & .length(S, N)
    & .member(Me, S) & queuedAhead(S, Me, K).

// the first waypoint of a team's sweep: the lanes turned by the robot's share (whole lanes: two
// waypoints each), once; resumeSweep keeps the order from then on
@shareSweep
+!nextWaypoint : not sweepShared & sweep(L) & sweepRank(K, N) & N > 1 & .length(L, Len) & Len > 1
    <- +sweepShared; Shift = 2 * ((K * (Len div 2)) div N);
       .findall(W, .range(I, 0, Len - 1) & .nth((I + Shift) mod Len, L, W), Shared);
       -+sweep(Shared); !nextWaypoint.
