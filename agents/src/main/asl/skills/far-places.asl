// Skill (a try, navigation's alone): a place remembered from a far sighting is forgotten at a delivery.
// A sighting from 1.2-1.5 m puts its cylinder 0.5-1 m off, and the search after a delivery went there
// first (wide world 107, seed 1: 84 s at two such places, one seen at 10 s from 1.54 m and 1 m from the
// cylinder); the look points cover that floor instead.
// Parameters:
farSighting(1.2).   // m: a place remembered farther than this from the robot is a far sighting
// Reads: seenCylinder(X, Z) (search memory), location, stored(N) (delivery).
// Beliefs: seenFar(X, Z) (a place remembered from a far sighting).
// Include it after search memory.
@seenFar +seenCylinder(Cx, Cz) : farSighting(F) & location(X, _, Z) & (Cx - X) * (Cx - X) + (Cz - Z) * (Cz - Z) > F * F <- +seenFar(Cx, Cz).
@seenFarForgotten -seenCylinder(Cx, Cz) : seenFar(Cx, Cz) <- -seenFar(Cx, Cz).
@farDroppedAtDelivery +stored(N) : N > 0 & seenFar(_, _) <- for (seenFar(X, Z)) { -seenCylinder(X, Z); -seenFar(X, Z) }.
