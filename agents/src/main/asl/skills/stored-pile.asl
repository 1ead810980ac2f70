// Skill: the stored pile left alone, not in the thesis (tidy-up's). The middleware signals a
// cylinder at the side of the camera's image (cylinderLeft, cylinderRight) and picking turns the robot
// to it and reaches for it; near the storage area, once something is stored there, that cylinder was
// the pile: the robot turned to it, the storage area's noAccess sent it away (and on to the sweep's
// next waypoint) and the reach waited 5 s for nothing, 1-3 times a run (tuning world 197: ten times in
// 150 s after its third delivery). Here a lateral cylinder is left alone while the storage point lies
// within pileNear ahead, within pileAngle of the robot's heading (the camera's 60 degrees and a margin).
// Parameters:
pileNear(0.5). pileAngle(35).   // m, degrees
// Reads: stored(N), storagePoint(X, Z) (delivery); location, orientation (the middleware).
// Include it before picking (its plans for +cylinderLeft and +cylinderRight come first).

pileInSight :- stored(N) & N > 0 & location(X, _, Z) & orientation(O) & storagePoint(Sx, Sz) & pileNear(R) & pileAngle(A)
    & Dx = Sx - X & Dz = Sz - Z & D = math.sqrt(Dx * Dx + Dz * Dz) & D < R & H = O * math.pi / 180
    & Dx * math.cos(H) + Dz * math.sin(H) > D * math.cos(A * math.pi / 180).
@pileOnTheLeft +cylinderLeft : pileInSight.
@pileOnTheRight +cylinderRight : pileInSight.
