// Skill: a search the team shares (thesis Chapter 6, multi-robot coordination; not in the thesis).
// Every robot swept the arena's lanes from the same corner, so a team searched the same places
// (held-out team worlds: four robots 2.3 times, two 1.3 times one robot's deliveries). The team's
// search map (the artifact "search") marks the floor each robot's camera has looked over (its place
// and heading, with every publication of its place: team-places), and gives a searching robot its
// next search point: a cylinder a teammate sighted on its way to the charger (a spot), else the
// nearest cell nobody has looked at, away from the other robots' points.
// The sweep (sweep.asl) drives to that point instead of its lanes' next waypoint; the point moves
// on as soon as anyone sees its cell (searchPoint(Me, X, Z), the map's), and a point reached or
// given up (the sweep's patience, an escape) is done. A robot alone keeps the sweep's lanes.
// Reads: arena(W, D), storagePoint(X, Z) (the world); storageClearance(C) (delivery); location,
// orientation, cylinderSighted (the middleware); picked(true) (picking); charging (recharge); searching,
// waypoint(X, Z, Since) (sweep); robotAt(A, X, Z) (team-places); searchPoint(A, X, Z) (the map);
// sightedAt, claimError, claimedByOther, carrierInSight, storedPileInSight (team-claims' rules);
// avoiding, picking, insideArea, atCharger (avoidance, picking, delivery, recharge).
// Needs: sweep (its !nextWaypoint and !sweepStep: this skill's plans come first), team-places
// (!lookedFrom), recovery (!escape). Include it before sweep, delivery and heading (its plan for
// +stuck comes before theirs).

// Parameters:
teamSearchAfter(5000).  // ms without a cylinder before a robot with teammates searches by the map
                        // (the sweep's own delay, 45 s, is a random walk's: alone, it covers floor
                        // the sweep's lanes would drive again)
setUpGoal(setUpTeamSearch).
searchDelay(S) :- teamSearch & teamSearchAfter(S).
teamSearch :- robotAt(A, _, _) & not .my_name(A).

@setUpTeamSearch
+!setUpTeamSearch : arena(W, D) & storagePoint(Sx, Sz) & storageClearance(C)
    <- lookupArtifact("search", S); focus(S); searchArea(W, D, Sx, Sz, C + 0.1).

// what the camera looked over: the floor a robot carrying a cylinder or on its way to the charger
// passes is not searched (it takes no cylinder then)
@lookedSearching
+!lookedFrom(X, Z) : teamSearch & orientation(O) & not picked(true) & not charging
    <- if (searching) { looked(X, Z, O, true) } else { looked(X, Z, O, false) }.
@lookedNot +!lookedFrom(_, _).

// a cylinder sighted on the way to the charger (no cylinder is taken then) is a spot on the map, a
// search point before any unseen floor; not one a teammate has claimed, carries or is about to take,
// nor the stored pile (team-claims' rules)
@spotWhileCharging
+cylinderSighted(Off, Dist) : teamSearch & charging & sightedAt(Off, Dist, Cx, Cz) & claimError(Dist, R)
    & not claimedByOther(Cx, Cz, R) & not teammateNear(Cx, Cz) & not carrierInSight(Off) & not storedPileInSight(Off)
    <- spotted(Cx, Cz).

// the sweep's next waypoint is the map's next search point
@teamNextWaypoint
+!nextWaypoint : teamSearch & location(X, _, Z)
    <- searchFrom(X, Z, Px, Pz); !searchPointAt(Px, Pz).
@searchPointAt +!searchPointAt(X, Z) <- .system_time(T); -+waypoint(X, Z, T); -+closest(1000); -+closerAt(T).

// the point moved on (its cell seen): head for the new one
@searchPointMoved
+!sweepStep : teamSearch & not seekingClaim(_, _, _, _) & .my_name(Me) & searchPoint(Me, X, Z) & waypoint(Wx, Wz, _) & (X \== Wx | Z \== Wz)
    <- !searchPointAt(X, Z); !sweepStep.
// a point reached: the next, without the sweep's look around at each waypoint (points are a cell apart)
@searchPointReached
+!sweepStep : teamSearch & waypoint(X, Z, _) & location(Lx, _, Lz) & (X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz) < 0.01
    <- !nextWaypoint.

// an avoidance cut off leaves "avoiding" behind: recovery's avoidance of an obstacle still seen
// runs inside the motion loop's move, and a lateral cylinder's reach ends that move
// (.succeed_goal(move(_))) before the avoidance takes "avoiding" back; every move then waits for
// it to go and no obstacle, no progress watch moves the robot again (team world 44, four robots,
// seed 1: a robot stood by the storage corner from 249 s to the end). No progress while
// "avoiding" is held by no avoidance: the sweep's escape
@stuckAvoidanceCutOff
+stuck : teamSearch & searching & avoiding & not picking & not insideArea & not atCharger
         & not .intend(avoid(_)) & not .intend(escape) & not .intend(leaveStorage)
    <- println("No progress, no avoidance under way: escaping"); .succeed_goal(move(_)); stop; !escape;
       -avoiding; !nextWaypoint.
