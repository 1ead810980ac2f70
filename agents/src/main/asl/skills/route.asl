// Skill: the way to a target point through a map the robot makes itself, not in the thesis (its
// robots head for a point by the compass and go round what they meet, heading.asl). The middleware
// puts every obstacle its distance sensors see on a grid of the arena (routeMap), forgets it when
// the robot stands where it was or routeMemory ms after it was last seen (boxes move), and plans
// round what is on the grid, the floor never seen taken as free (routeTo: A* over the grid). The
// robot heads for the farthest point of that route it can reach in a straight line: the target
// itself while nothing met is in the way, and also when no way round is known (today's heading).
// Each re-alignment plans again (heading's detour after an obstacle met, its steering every
// heading's bendSteerEvery ms while the route bends; the sweep's every step), so a wall met is learnt and
// gone round, a doorway found is remembered, and the way back from the charger takes the way out.
// Parameters:
routeMemory(180000).   // ms an obstacle seen stays on the map
// m: this near the target the robot heads for it straight (the storage area and the charger are
// entered with the distance sensors off and no steering: a point beside the target took it past)
routeNear(0.3).
// m: with routeHold, a held point this near is reached and the way planned again (a sweep step, 2 s,
// goes about 0.1 m; the point lies at most 0.2 m on: RouteMap.LOOKAHEAD)
routeReach(0.1).
// Reads: arena(W, D) (the world); wallGuess(M), wallFirm(F) (an agent's options, below); lastAvoid(T)
// (avoidance); routeHold(H) (an agent's option, e.g. suspend/resume's: the sweep keeps the point
// its route gave for up to H ms, until it is within routeReach of it or an obstacle was avoided
// since, instead of planning again every step, where the aim, re-planned from each new spot, swung
// left and right near its waypoint: docs/comparison-wide.md); travelling (delivery: the trips plan
// at every re-alignment).
// Beliefs: routePlanning (heading, sweep and way-round read it: the trips take the route, the
// boundary following stands aside), aim(X, Z) (the point headed for now), aimChosen(X, Z, T) (with
// routeHold: the sweep's target and when its aim was planned); the rule nearTarget(X, Z) (within
// routeNear of the point).
// Needs: a middleware with the GPS (NavigationMiddleware: routeMap, routeTo). Include it before
// delivery (heading's +!aimAt plans come after its own). Suspend/resume includes it, with way-back.asl
// and routeHold (a gain on the wide worlds: docs/comparison-wide.md);
// navigation does not (alone, no clear gain over heading and way-round: "The way through the robot's
// own map").

routePlanning.
setUpGoal(setUpRoute).

// an agent's wallGuess(M) (suspend/resume's): a wall's face seen is taken to go on M metres past its
// seen end, where the robot has not driven (RouteMap: a doorway driven through is taken first); with
// wallFirm(F) too, its first F metres are crossed only at a high cost, and a side sensor that sees the
// floor open ends it (RouteMap.guessWallsFirm: a route along a wall crosses past the firm part, where
// it turned into the wall's unseen part at every plan, not past the end seen)
@setUpRoute +!setUpRoute : arena(W, D) & routeMemory(M)
    <- routeMap(W, D, M); if (wallGuess(G)) { routeWallGuess(G) }; if (wallGuess(_) & wallFirm(F)) { routeWallFirm(F) }.

// within routeNear of (Tx, Tz): the robot heads for it straight (tidy-up's re-alignment reads it too)
nearTarget(Tx, Tz) :- location(X, _, Z) & routeNear(N) & (X - Tx) * (X - Tx) + (Z - Tz) * (Z - Tz) < N * N.
// the point to head for on the way to (Tx, Tz): the route's, believed as aim(X, Z)
@aimNearTarget
+!aimAt(Tx, Tz) : routePlanning & nearTarget(Tx, Tz)
    <- -+aim(Tx, Tz).
// the held point: for H ms at most, until the robot is within routeReach of it (a point it passed
// pulled it back) or an obstacle turned it away since (the point may lie behind it)
holdOn(Tx, Tz) :- routeHold(H) & aimChosen(Tx, Tz, T0) & .system_time(T) & T - T0 < H & not (lastAvoid(A) & A >= T0)
    & aim(Ax, Az) & location(X, _, Z) & routeReach(R) & (X - Ax) * (X - Ax) + (Z - Az) * (Z - Az) > R * R.
@aimHeld
+!aimAt(Tx, Tz) : routePlanning & not travelling & holdOn(Tx, Tz).
@aimOnRouteHeld
+!aimAt(Tx, Tz) : routePlanning & routeHold(_) & not travelling
    <- routeTo(Tx, Tz, Wx, Wz); -+aim(Wx, Wz); .system_time(T); -+aimChosen(Tx, Tz, T).
@aimOnRoute +!aimAt(Tx, Tz) : routePlanning <- routeTo(Tx, Tz, Wx, Wz); -+aim(Wx, Wz).
