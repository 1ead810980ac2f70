// Skill: working in a team (thesis Chapter 6, multi-robot coordination; after the claims of Jason's
// gold-miners, kept in artifacts as JaCa would). Every robot's agent is named as its robot and
// focuses its own middleware artifact (middleware_<name>), the team's task board (board) and the
// charger's queue (charger), all made by the team's runner.
// - A cylinder sighted far off is claimed on the board at its estimated place (from the robot's
//   location, orientation and the sighting's offset and distance) before homing on it; a cylinder
//   another robot has claimed (claimed_by) is ignored from then on, and the robot looks on.
// - The claim is completed when the cylinder is put down in the storage area (stored(N) grows),
//   released when the homing is given up (out of sight, chased too long) or the battery runs low.
// - A robot whose battery runs low queues for the charger (requestCharger, awaitCharger) where it
//   stands before going there, and leaves the queue once recharged (leaveCharger).
// Parameters:
ignoreClaimed(0.15).   // m around a cylinder another robot has claimed that this one stops seeing
// Beliefs: myClaim(Id), claimRefused.
// Needs: initial-phase (!init), far-sight (+!sighted, !homeOn), recharge (!awaitChargerTurn,
// !chargerDone), delivery (stored(N)). Include it FIRST: its plans for !init, !sighted,
// !awaitChargerTurn and !chargerDone come before the skills' defaults.

setUpGoal(setUpTeam).

@findOwnMiddleware +!init(Id) : .my_name(Me) <- .concat("middleware_", Me, Name); lookupArtifact(Name, Id).
@setUpTeam +!setUpTeam <- lookupArtifact("board", B); focus(B); lookupArtifact("charger", C); focus(C).

/* Claims on the task board */

@claimSighted
+!sighted(Off, Dist) : location(X, _, Z) & orientation(O)
    <- A = (O + Off) * math.pi / 180; Cx = X + Dist * math.cos(A); Cz = Z + Dist * math.sin(A);
       -claimRefused; !claim(Cx, Cz);
       if (not claimRefused) { !homeOn(Off, Dist) }.

// the board gives the same claim back for a place near the caller's own; another is a new cylinder
@claim +!claim(Cx, Cz) <- claim(Cx, Cz, Id); !dropOtherClaim(Id); -+myClaim(Id).
@claimedByOther
-!claim(Cx, Cz)[env_failure_reason(claimed_by(Other, _))] : ignoreClaimed(R)
    <- +claimRefused; ignoreCylindersNear(Cx, Cz, R); .print("That cylinder is ", Other, "'s: looking elsewhere").
@claimFailed -!claim(_, _)[error_msg(M)] <- +claimRefused; .print("claim failed: ", M).

@dropOtherClaim +!dropOtherClaim(Id) : myClaim(Old) & Old \== Id <- release(Old); -myClaim(Old).
@keepClaim +!dropOtherClaim(_).

@completeClaim +stored(N) : N > 0 & myClaim(Id) <- complete(Id); -myClaim(Id); .print("Claim ", Id, " completed").
// recovery plans that give a cylinder up give its claim up
@releaseOnGiveUp
-homing(_) : myClaim(Id) & not picked(true) & not picking <- release(Id); -myClaim(Id); .print("Claim ", Id, " released").
@releaseOnCharging +charging : myClaim(Id) & not picked(true) <- release(Id); -myClaim(Id).

/* One charger for the team */

@awaitChargerTurn
+!awaitChargerTurn <- stop; requestCharger; .print("Waiting for the charger"); awaitCharger; .print("The charger is mine").
@leaveChargerQueue +!chargerDone <- leaveCharger.
// a recharge given up (a fallen cylinder drops every desire and forgets "charging") leaves the
// queue too, else its robot held the charger for the rest of the run; with a cylinder being
// delivered, recharge's own plan for -charging resumes the delivery (the queue is left already)
@leaveChargerOnGiveUp -charging : not delivering <- leaveCharger.
