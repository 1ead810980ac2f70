// Skill: where the teammates are (thesis Chapter 6, multi-robot coordination; not in the thesis).
// A robot's distance sensors see another robot only as an obstacle, and its camera sees the red
// cylinder another robot carries as a cylinder: every robot publishes its place on the team's task
// board (at(X, Z): robotAt(Agent, X, Z) for all to perceive) every placeEvery, so that the
// others can tell a teammate (and what it carries or is about to take) from the rest.
// Parameters:
placeEvery(400).           // ms between two publications of the robot's place (team-way reads them)
teammateClearance(0.15).   // m: a sighting this near a teammate's last published place is the
                           // teammate's (a cylinder carried 6 cm ahead, a robot's second of travel)
// Beliefs: placePublished(T). Reads: location(X, Y, Z) (the middleware), robotAt(A, X, Z) (the board).
// Rules it offers: teammateNear(X, Z). Goals it offers: !waitPublishing(T) (a wait that publishes the
// place every placeEvery, for a manoeuvre that holds the agent: team-way's).
// Needs: the board focused (team-claims' setUpTeam); !lookedFrom (team-search: the floor the camera
// looked over, marked on the team's search map). Include it after team-storage.

placeDue(_) :- not placePublished(_).
placeDue(T) :- placePublished(T0) & placeEvery(E) & T - T0 >= E.
teammateNear(X, Z) :- teammateClearance(R) & teammateWithin(X, Z, R).
teammateWithin(X, Z, D) :- robotAt(A, Ax, Az) & not .my_name(A) & (Ax - X) * (Ax - X) + (Az - Z) * (Az - Z) < D * D.

// driven by the GPS percept, so that no drop of every desire (a fallen cylinder) ends it; a skill
// with a plan for +location that applies now and then (team-storage) is included before this one
@publishPlace[atomic]
+location(X, _, Z) : .system_time(T) & placeDue(T)
    <- -+placePublished(T); at(X, Z); !lookedFrom(X, Z).

// An atomic manoeuvre (team-way's give-way) holds back @publishPlace, and the teammate it gives way
// to stops for it only on a fresh place (team-way's @stopForTeammate): a give-way of 600 ms left a
// stale place on the board, and the one behind drove on into it (a replay of team world 45, four robots).
@waitPublishingLast +!waitPublishing(T) : placeEvery(E) & T <= E <- .wait(T); !publishPlaceNow.
@waitPublishing +!waitPublishing(T) : placeEvery(E) <- .wait(E); !publishPlaceNow; !waitPublishing(T - E).
@publishPlaceNow +!publishPlaceNow : location(X, _, Z) & .system_time(T) <- -+placePublished(T); at(X, Z).
@noPlaceYet +!publishPlaceNow.
