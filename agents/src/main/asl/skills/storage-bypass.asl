// Skill: the sweep goes round the storage area, not in the thesis. The sweep's lanes run straight
// across the arena and its waypoints keep laneClearance from the storage point (sweep.asl), but a
// lane between two waypoints may cross the storage area, anywhere on the floor in users' arenas. There
// the robot, empty, met noAccess (delivery: turned away, on to the next waypoint, often across the
// area again) and the camera showed the cylinders stored there as lateral ones to reach (picking):
// in wide world 262 (navigation, seed 1) it went to and fro across the area from 270 s to the end,
// and found no second cylinder. While the straight way to the sweep's waypoint passes within
// laneClearance of the storage point, the robot heads for the point beside the area, bypassAside
// beyond laneClearance, on the side the way passes (the side towards the arena's centre if it passes
// through the point itself); past the area, the way is clear and it heads for the waypoint again.
// Parameters:
bypassAside(0.05).   // m beyond laneClearance the point beside the storage area lies
// Reads: location; arena(W, D), storagePoint(X, Z) (the world); searching, waypoint(X, Z, T),
// laneClearance(L) (sweep); travelling (delivery: a trip's heading is not the sweep's).
// Beliefs: aim(X, Z) (heading's: the point headed for).
// Needs: sweep (its steps head for aim via !aimAt). Include it before delivery (heading's +!aimAt
// plans come after its own) and before route.asl when both are included.

// the point of the way from (Lx, Lz) to (X, Z) nearest (Sx, Sz), when it lies between the two ends
wayFoot(Lx, Lz, X, Z, Sx, Sz, Fx, Fz) :- Dx = X - Lx & Dz = Z - Lz & L2 = Dx * Dx + Dz * Dz & L2 > 0.0001
    & U = ((Sx - Lx) * Dx + (Sz - Lz) * Dz) / L2 & U > 0 & U < 1 & Fx = Lx + U * Dx & Fz = Lz + U * Dz.
passesStorage(X, Z, Fx, Fz) :- location(Lx, _, Lz) & storagePoint(Sx, Sz) & laneClearance(R)
    & wayFoot(Lx, Lz, X, Z, Sx, Sz, Fx, Fz) & (Fx - Sx) * (Fx - Sx) + (Fz - Sz) * (Fz - Sz) < R * R.

@aimBesideStorage
+!aimAt(X, Z) : searching & not travelling & waypoint(X, Z, _) & passesStorage(X, Z, Fx, Fz)
               & storagePoint(Sx, Sz) & laneClearance(R) & bypassAside(A) & location(Lx, _, Lz) & arena(W, D)
    <- N = math.sqrt((Fx - Sx) * (Fx - Sx) + (Fz - Sz) * (Fz - Sz));
       if (N > 0.01) { Nx = (Fx - Sx) / N; Nz = (Fz - Sz) / N }
       else {
           L = math.sqrt((X - Lx) * (X - Lx) + (Z - Lz) * (Z - Lz)); Px = (Lz - Z) / L; Pz = (X - Lx) / L;
           if (Sx * Px + Sz * Pz > 0) { Nx = -Px; Nz = -Pz } else { Nx = Px; Nz = Pz }
       };
       Ax = math.max(0.1 - W / 2, math.min(W / 2 - 0.1, Sx + (R + A) * Nx));
       Az = math.max(0.1 - D / 2, math.min(D / 2 - 0.1, Sz + (R + A) * Nz));
       -+aim(Ax, Az).
