// Skill: the way back the robot came, not in the thesis. The middleware keeps the robot's own trail
// (keepTrail: a GPS point every 4 cm driven, points within 6 cm joined: the robot passed there
// again) and gives the point to head for along the shortest way through it (trailTo). Every
// stretch of the trail was driven, so it holds the doorway of a wall the robot once went round,
// which its 6 cm infra-red never shows from afar. Two trips take it:
// - the way back from the charger to the marked point (recharge-trip): the way out, its loops cut;
// - a trip that meets a wall (way-round's !wallMet, an obstacle met again near an earlier one) to a
//   target the trail passed near: back through the doorway it came by, where the boundary following
//   would choose a side blind and crawl along the wall (1-2 cm/s against 5 cm/s cruising).
// Otherwise (no trail near the robot and the target) the target itself, as heading.asl.
// Reads: targetPoint(X, Z), travelling (heading, delivery, recharge-trip); charging, charger(X, Z)
// (recharge-trip, the world).
// Beliefs: onTrail (this trip goes along the trail), trailSince(N) (heading's detours(N) when it began);
// routePlanning while on it (way-round's boundary following stands aside), aim(X, Z) (heading's:
// the point headed for).
// Needs: a middleware with the GPS (NavigationMiddleware: keepTrail, trailTo), heading.asl. Include
// it before way-round and delivery (its !aimAt and !wallMet plans come before theirs).

// Parameters:
trailDetours(12).   // obstacles gone round on the trail in one trip before it is taken for blocked (a box moved onto it)
setUpGoal(setUpTrail).

@setUpTrail +!setUpTrail <- keepTrail.

// the way back from the charger: recharge-trip's target is the marked point, not the charger
returning :- charging & targetPoint(X, Z) & charger(Cx, Cz) & (X \== Cx | Z \== Cz).
// the trail is blocked on this trip once trailDetours obstacles were gone round on it (heading's
// detours count the trip's; the way back starts at 0)
trailSince(0).
trailBlocked :- trailSince(D) & detours(N) & trailDetours(K) & N - D >= K.
byTrail :- (onTrail | returning) & not trailBlocked.
routePlanning :- onTrail & travelling & not trailBlocked.

// a new trip (way-round's hook): the trail only once a wall is met again (or on the way back)
@trailNewTrip +!tripBegun <- -onTrail; -+trailSince(0).

@aimAlongTrail
+!aimAt(Tx, Tz) : byTrail <- trailTo(Tx, Tz, Wx, Wz); -+aim(Wx, Wz).

// a wall between the robot and its target: back along the trail when it knows a way there
@wallMetTrail
+!wallMet(Dist) : travelling & targetPoint(Tx, Tz) & not trailBlocked <- trailTo(Tx, Tz, Wx, Wz); !trailOrFollow(Tx, Tz, Wx, Wz, Dist).
@noTrailThere +!trailOrFollow(Tx, Tz, Tx, Tz, Dist) <- !startFollowing(Dist, _).
@alongTrail
+!trailOrFollow(_, _, _, _, _)
    <- +onTrail; ?detours(D); -+trailSince(D); -avoiding; println("A wall between the robot and its target: the way it came"); !computeGap; !!balance.
