// Skill: claims on the team's task board (thesis Chapter 6, multi-robot coordination; after the
// claims of Jason's gold-miners, kept in artifacts as JaCa would). Every robot's agent is named as
// its robot and focuses its own middleware artifact (middleware_<name>), the team's task board
// (board) and the charger's queue (charger), all made by the team's runner.
// - A cylinder sighted far off is claimed on the board at its estimated place (from the robot's
//   location, orientation and the sighting's offset and distance) give or take how far off such an
//   estimate may be (claimError: grows with the distance) before homing on it; every later sighting
//   of it renews the claim, nearer and narrower. The claim is that disc swept on along the
//   sighting's bearing, claimBeyond times its radius beyond the estimate (claimAlong): a cylinder
//   half hidden seems nearer than it is (one 0.69 m away estimated at 0.39 m, behind a box), and
//   two robots' discs round such estimates of one cylinder, from two sides, missed each other
//   (team world 12, four robots: a double claim). A sighting is left alone while its disc overlaps
//   another robot's claim (only while it is claimed: a released claim's cylinder is anyone's again)
//   or lies near a teammate (team-places: the cylinder it is about to take); the board refuses a
//   claim whose disc overlaps another's (claimed_by) in the same operation that makes it.
// - A sighting's bearing is good, its distance is not: a sighting in the line of a teammate that
//   carries a cylinder, or of the storage area once a cylinder is stored there, may be that
//   cylinder (or the pile) estimated far off its place, and is left alone while it is so. (A robot
//   homed on the stored pile seen 0.65 m away and estimated 0.19 m away; its claim passed within
//   0.3 m of the cylinder a teammate carried by: a double claim, world 1 with four robots.)
// - A cylinder picked up is taken on the board where it was (take): whatever other claim may name
//   it is void, as the cylinder is this robot's in fact, and the claim follows the robot (the
//   board moves it with the robot's published place) until the cylinder is let go (putDown).
// - The claim is completed when the cylinder is put down in the storage area (stored(N) grows),
//   released when the homing is given up (out of sight, chased too long) or the battery runs low.
// Parameters:
claimErrorBase(0.08).  // m: how far off a sighting's estimated place may be, at no distance ...
claimErrorSlope(0.3).  // ... plus this much per metre of distance (measured on generated team
                       // worlds: up to 0.45 m off at 1.4 m, 0.28 m at 0.75 m, 0.19 m at 0.4 m)
seekClaimTime(20000).  // ms a claim lost from sight is kept while its robot looks for it again
claimBeyond(2).        // the claim reaches this many times its radius beyond the estimate, on the bearing
sightCone(15).         // degrees either side of a sighting's bearing where a carried cylinder or the
                       // stored pile may be what was sighted
// Beliefs: myClaim(Id), claimRefused, takenCaught, seekingClaim(Id, X, Z, Since), claimViewedSince(T). Reads: caught(B) (the middleware), teamSearch (team-search), claimed(Id, A, X, Z, R), completed(N) (the board),
// robotAt(A, X, Z) (team-places), storagePoint(X, Z) (the world), location, orientation, homing(_)
// (far-sight), cylinderLeft, cylinderRight (the middleware: its plans come before picking's).
// Needs: initial-phase (!init), far-sight (+!sighted, !homeOn), picking (picked(true); its gripper's
// gripPoint: where a held cylinder is), delivery
// (stored(N)), team-places (teammateNear, teammateWithin), team-storage (awayFromStorage). Include it FIRST (after team-places): its plans for
// !init and !sighted come before the skills' defaults.

setUpGoal(setUpTeam).

// where a sighting's cylinder lies, estimated from the robot's place and heading
sightedAt(Off, Dist, Cx, Cz) :- location(X, _, Z) & orientation(O) & A = (O + Off) * math.pi / 180
    & Cx = X + Dist * math.cos(A) & Cz = Z + Dist * math.sin(A).
claimError(Dist, R) :- claimErrorBase(B) & claimErrorSlope(S) & R = B + S * Dist.
// the far end of a sighting's claim, on its bearing beyond the estimate
claimEnd(Off, Dist, R, Fx, Fz) :- location(X, _, Z) & orientation(O) & claimBeyond(K) & A = (O + Off) * math.pi / 180
    & Fx = X + (Dist + K * R) * math.cos(A) & Fz = Z + (Dist + K * R) * math.sin(A).
// the board's own rule: two discs that overlap may be one cylinder
claimedByOther(X, Z, R) :- claimed(_, A, Cx, Cz, Rc) & not .my_name(A)
    & (X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz) < (R + Rc) * (R + Rc).

// the point (Px, Pz) lies within sightCone of the bearing of a sighting at Off degrees
inSightLine(Off, Px, Pz) :- location(X, _, Z) & orientation(O) & sightCone(C) & A = (O + Off) * math.pi / 180
    & Dx = Px - X & Dz = Pz - Z & D = math.sqrt(Dx * Dx + Dz * Dz) & D > 0
    & Dx * math.cos(A) + Dz * math.sin(A) > D * math.cos(C * math.pi / 180).
// a teammate that carries a cylinder (its claim follows its published place) in the sighting's line
carrierInSight(Off) :- robotAt(A, Ax, Az) & not .my_name(A) & claimed(_, A, Ax, Az, _) & inSightLine(Off, Ax, Az).
storedPileInSight(Off) :- completed(N) & N > 0 & storagePoint(Sx, Sz) & inSightLine(Off, Sx, Sz).

@findOwnMiddleware +!init(Id) : .my_name(Me) <- .concat("middleware_", Me, Name); lookupArtifact(Name, Id).
@setUpTeam +!setUpTeam <- lookupArtifact("board", B); focus(B); lookupArtifact("charger", C); focus(C).

// Not in the thesis: with teammates, a red side of the camera image is not reached for (picking's
// lateral reach, a slow turn then a slow approach, which passes by the board's claims) while the
// robot homes on a sighting (far sight steers to it), nor while the stored pile or a teammate that
// carries lies in that side's line. Four robots, team tuning worlds 1-24: 237 lateral reaches, 27
// ended at a cylinder; 1233 of their 2419 s within 30 s after a delivery (the stored pile at the side).
lateralOff(_) :- homing(_).
lateralOff(Off) :- storedPileInSight(Off).
lateralOff(Off) :- carrierInSight(Off).
@lateralLeftOff +cylinderLeft : teamSearch & lateralOff(-20).
@lateralRightOff +cylinderRight : teamSearch & lateralOff(20).

/* Claims on the task board */

@sightedClaimedByOther
+!sighted(Off, Dist) : sightedAt(Off, Dist, Cx, Cz) & claimError(Dist, R) & claimedByOther(Cx, Cz, R).
@sightedNearTeammate +!sighted(Off, Dist) : sightedAt(Off, Dist, Cx, Cz) & teammateNear(Cx, Cz).
@sightedCarriedCylinder +!sighted(Off, _) : carrierInSight(Off).
@sightedStoredPile +!sighted(Off, _) : storedPileInSight(Off).
@claimSighted
+!sighted(Off, Dist) : sightedAt(Off, Dist, Cx, Cz) & claimError(Dist, R) & claimEnd(Off, Dist, R, Fx, Fz)
    <- -claimRefused; !claim(Cx, Cz, R, Fx, Fz);
       if (not claimRefused) { !homeOn(Off, Dist) }.

// the board gives the same claim back for a disc that overlaps the caller's own; another is a new cylinder
@claim +!claim(Cx, Cz, R, Fx, Fz) <- claimAlong(Cx, Cz, R, Fx, Fz, Id); !dropOtherClaim(Id); -+myClaim(Id).
@claimedByOther
-!claim(_, _, _, _, _)[env_failure_reason(claimed_by(Other, _))] <- +claimRefused; .print("That cylinder is ", Other, "'s: looking elsewhere").
@claimFailed -!claim(_, _, _, _, _)[error_msg(M)] <- +claimRefused; .print("claim failed: ", M).

@dropOtherClaim +!dropOtherClaim(Id) : myClaim(Old) & Old \== Id <- !releaseClaim(Old, another(Id)).
@keepClaim +!dropOtherClaim(_).

// the claim's place near and ahead, where far sight shows a cylinder (within 20 degrees, 0.1-0.8 m)
claimPlaceInView(Cx, Cz) :- location(X, _, Z) & orientation(O) & Dx = Cx - X & Dz = Cz - Z
    & D = math.sqrt(Dx * Dx + Dz * Dz) & D < 0.8 & D > 0.1 & H = O * math.pi / 180
    & Dx * math.cos(H) + Dz * math.sin(H) > D * math.cos(20 * math.pi / 180).

// the cylinder in the gripper is this robot's, whoever had claimed its place
@takePicked
+picked(true) : gripPoint(Hx, Hz) <- .abolish(seekingClaim(_, _, _, _)); -takenCaught; take(Hx, Hz, Id); -myClaim(_); +myClaim(Id).
// with teammates, taken as soon as the gripper holds it (caught), the arm still down: until picked
// (a second later) a teammate's claim on it stood while this robot held it, a double claim (team
// world 86, two robots, a cylinder reached at the robot's side); let go before it was picked, its
// claim stays where it is, as a fallen cylinder's
@takeCaught
+caught(true) : teamSearch & picking & not picked(true) & gripPoint(Hx, Hz)
    <- .abolish(seekingClaim(_, _, _, _)); +takenCaught; take(Hx, Hz, Id); -myClaim(_); +myClaim(Id).
@caughtLetGo
+caught(false) : takenCaught & not picked(true) & gripPoint(Hx, Hz) <- -takenCaught; putDown(Hx, Hz).
// the cylinder let go (put down in the storage area, or fallen): its claim stays where it is
@putDownClaim
-picked(true) : myClaim(_) & gripPoint(Hx, Hz) <- putDown(Hx, Hz).
// a claim the board voided (another robot took the cylinder) is forgotten
@claimVoided -claimed(Id, Me, _, _, _) : myClaim(Id) & .my_name(Me) & not claimed(Id, _, _, _, _) & not picked(true) <- -myClaim(Id).

// an intention of its own: a claim no longer on the board must not end the delivery that stored
// the cylinder (the robot stood in the storage area, its turn kept, for a minute)
@completeClaim +stored(N) : N > 0 & myClaim(Id) <- -myClaim(Id); !!completeClaim(Id).
@completeClaimOnBoard +!completeClaim(Id) <- complete(Id); .print("Claim ", Id, " completed").
@claimGoneAtCompletion
-!completeClaim(Id)[error_msg(M)] <- .print("Claim ", Id, " not completed: ", M).
// Not in the thesis: with teammates, a claim whose cylinder was lost from sight (not a homing given
// up) is kept while its robot drives back to the claim's place to look again (seekingClaim): released
// at once, its cylinder was left (323 claims released against 158 completed, four robots, team
// worlds 1-24), and the teammates had passed it over as this robot's. It is released once the place
// lies near and ahead with no sighting for 2 s (claimPlaceInView), after seekClaimTime, or when the
// robot's search moves on (!nextWaypoint: reached, skipped, an escape); a new homing ends the seek.
// Not by the storage area (team-storage's awayFromStorage), where the teammates deliver, nor with a
// teammate within 0.5 m of the robot or of the place, and given up once one comes within 0.4 m of the
// place: robots seeking again met teammates there (held out, four robots: contact under 2 s in 79 of 90 runs).
@seekLostClaim
-homing(_) : myClaim(Id) & not picked(true) & not picking & lastSighted(_) & location(_, _, _) & .my_name(Me)
    & claimed(Id, Me, Cx, Cz, _) & not unsoughtWhy(_) & .system_time(T)
    <- .abolish(seekingClaim(_, _, _, _)); .abolish(claimViewedSince(_)); +seekingClaim(Id, Cx, Cz, T);
       -+waypoint(Cx, Cz, T); -+closest(1000); -+closerAt(T); .print("Claim ", Id, " lost from sight: looking again").
// recovery plans that give a cylinder up give its claim up
@releaseOnGiveUp
-homing(_) : myClaim(Id) & not picked(true) & not picking & .findall(W, unsoughtWhy(W), Why)
    <- !releaseClaim(Id, homingOver(Why)); .print("Claim ", Id, " released").
@releaseOnCharging +charging : myClaim(Id) & not picked(true) <- .abolish(seekingClaim(_, _, _, _)); !releaseClaim(Id, charging).
// why a homing's end does not seek its claim again: @seekLostClaim's context is that none holds (with
// the last sighting, the robot's place and the claim known); the board's log of a release gives them
unsoughtWhy(alone) :- not teamSearch.
unsoughtWhy(notSearching) :- not searching.
unsoughtWhy(charging) :- charging.
unsoughtWhy(inSight) :- lastSighted(S) & .system_time(T) & T - S < 1500.
unsoughtWhy(byStorage) :- myClaim(Id) & .my_name(Me) & claimed(Id, Me, Cx, Cz, _) & not awayFromStorage(Cx, Cz).
unsoughtWhy(teammateByRobot) :- location(X, _, Z) & teammateWithin(X, Z, 0.5).
unsoughtWhy(teammateByClaim) :- myClaim(Id) & .my_name(Me) & claimed(Id, Me, Cx, Cz, _) & teammateWithin(Cx, Cz, 0.5).

// the claim sought again: a homing (the same cylinder claimed again, or another) ends the seek
@seekEndsHoming +homing(_) : seekingClaim(_, _, _, _) <- .abolish(seekingClaim(_, _, _, _)); .abolish(claimViewedSince(_)).
// gone from its place (in view, near, for 2 s: far sight would have homed on it), or sought too long
@seekClaimInView
+!sweepStep : seekingClaim(Id, Cx, Cz, T0) & myClaim(Id) & claimPlaceInView(Cx, Cz) & not ignoring & not claimViewedSince(_)
    <- .system_time(T); +claimViewedSince(T); !sweepStep.
@seekClaimOver
+!sweepStep : seekingClaim(Id, Cx, Cz, T0) & .system_time(T) & seekClaimTime(W)
    & (T - T0 > W | claimViewedSince(V) & T - V > 2000 | not myClaim(Id) | teammateWithin(Cx, Cz, 0.4))
    <- !endSeek; !nextWaypoint.
@seekNextWaypoint +!nextWaypoint : seekingClaim(_, _, _, _) <- !endSeek; !nextWaypoint.
@endSeek
+!endSeek : seekingClaim(Id, _, _, _)
    <- .abolish(seekingClaim(_, _, _, _)); .abolish(claimViewedSince(_));
       if (myClaim(Id)) { !releaseClaim(Id, notFoundAgain); .print("Claim ", Id, " released: not found again") }.
@endSeekNone +!endSeek <- .abolish(claimViewedSince(_)).

// the belief goes first: a claim the board has voided meanwhile (another robot took its cylinder)
// is not this robot's any more, and no later claim must fail on releasing it. A claim is released
// once: a homing given up as the battery runs low had both release it (-homing, +charging), and the
// second release failed inside the recharge trip's atomic start (team world 80, two robots, seed 2)
// the reason goes to the board, which logs the release with it and the claim's place: another(New)
// (a new claim), homingOver(Why) (the homing ended, not sought again: unsoughtWhy), notFoundAgain
// (sought again), charging
@releaseClaim +!releaseClaim(Id, Why) : myClaim(Id) <- -myClaim(Id); release(Id, Why).
@claimReleasedAlready +!releaseClaim(_, _).
@claimGoneAlready -!releaseClaim(_, _).
