// Skill: claims on the team's task board (thesis Chapter 6, multi-robot coordination; after the
// claims of Jason's gold-miners, kept in artifacts as JaCa would). Every robot's agent is named as
// its robot and focuses its own middleware artifact (middleware_<name>), the team's task board
// (board) and the charger's queue (charger), all made by the team's runner.
// - A cylinder sighted far off is claimed on the board at its estimated place (from the robot's
//   location, orientation and the sighting's offset and distance) before homing on it. A sighting
//   is left alone while it lies near another robot's claim (only while it is claimed: a released
//   claim's cylinder is anyone's again) or near a teammate (team-places: the cylinder it carries or
//   is about to take); the board refuses a claim near another's (claimed_by), at once for all.
// - A cylinder picked up is taken on the board where it was (take): whatever other claim named it
//   is void, as the cylinder is this robot's in fact.
// - The claim is completed when the cylinder is put down in the storage area (stored(N) grows),
//   released when the homing is given up (out of sight, chased too long) or the battery runs low.
// Parameters:
ignoreClaimed(0.3).   // m around another robot's claim where sightings are left alone (wider than
                      // the board's 0.2 m: two estimates of one cylinder 0.25 m apart were two claims)
gripReach(0.06).      // m from the robot's centre to a cylinder held in the gripper
// Beliefs: myClaim(Id), claimRefused.
// Needs: initial-phase (!init), far-sight (+!sighted, !homeOn), picking (picked(true)), delivery
// (stored(N)), team-places (teammateNear). Include it FIRST (after team-places): its plans for
// !init and !sighted come before the skills' defaults.

setUpGoal(setUpTeam).

// where a sighting's cylinder lies, estimated from the robot's place and heading
sightedAt(Off, Dist, Cx, Cz) :- location(X, _, Z) & orientation(O) & A = (O + Off) * math.pi / 180
    & Cx = X + Dist * math.cos(A) & Cz = Z + Dist * math.sin(A).
claimedByOther(X, Z) :- claimed(_, A, Cx, Cz) & not .my_name(A) & ignoreClaimed(R)
    & (X - Cx) * (X - Cx) + (Z - Cz) * (Z - Cz) < R * R.

@findOwnMiddleware +!init(Id) : .my_name(Me) <- .concat("middleware_", Me, Name); lookupArtifact(Name, Id).
@setUpTeam +!setUpTeam <- lookupArtifact("board", B); focus(B); lookupArtifact("charger", C); focus(C).

/* Claims on the task board */

@sightedClaimedByOther +!sighted(Off, Dist) : sightedAt(Off, Dist, Cx, Cz) & claimedByOther(Cx, Cz).
@sightedNearTeammate +!sighted(Off, Dist) : sightedAt(Off, Dist, Cx, Cz) & teammateNear(Cx, Cz).
@claimSighted
+!sighted(Off, Dist) : sightedAt(Off, Dist, Cx, Cz)
    <- -claimRefused; !claim(Cx, Cz);
       if (not claimRefused) { !homeOn(Off, Dist) }.

// the board gives the same claim back for a place near the caller's own; another is a new cylinder
@claim +!claim(Cx, Cz) <- claim(Cx, Cz, Id); !dropOtherClaim(Id); -+myClaim(Id).
@claimedByOther
-!claim(_, _)[env_failure_reason(claimed_by(Other, _))] <- +claimRefused; .print("That cylinder is ", Other, "'s: looking elsewhere").
@claimFailed -!claim(_, _)[error_msg(M)] <- +claimRefused; .print("claim failed: ", M).

@dropOtherClaim +!dropOtherClaim(Id) : myClaim(Old) & Old \== Id <- !releaseClaim(Old).
@keepClaim +!dropOtherClaim(_).

// the cylinder in the gripper is this robot's, whoever had claimed its place
@takePicked
+picked(true) : location(X, _, Z) & orientation(O) & gripReach(G)
    <- A = O * math.pi / 180; take(X + G * math.cos(A), Z + G * math.sin(A), Id); -myClaim(_); +myClaim(Id).
// a claim the board voided (another robot took the cylinder) is forgotten
@claimVoided -claimed(Id, Me, _, _) : myClaim(Id) & .my_name(Me) & not claimed(Id, _, _, _) & not picked(true) <- -myClaim(Id).

@completeClaim +stored(N) : N > 0 & myClaim(Id) <- -myClaim(Id); complete(Id); .print("Claim ", Id, " completed").
// recovery plans that give a cylinder up give its claim up
@releaseOnGiveUp
-homing(_) : myClaim(Id) & not picked(true) & not picking <- !releaseClaim(Id); .print("Claim ", Id, " released").
@releaseOnCharging +charging : myClaim(Id) & not picked(true) <- !releaseClaim(Id).

// the belief goes first: a claim the board has voided meanwhile (another robot took its cylinder)
// is not this robot's any more, and no later claim must fail on releasing it
@releaseClaim +!releaseClaim(Id) <- -myClaim(Id); release(Id).
@claimGoneAlready -!releaseClaim(_).
