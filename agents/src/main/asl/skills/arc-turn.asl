// Skill: turning on the way in an arc, not in the thesis. Heading's re-alignment stops the robot
// and turns it on the spot until it faces the point it heads for within 0.6 degrees (the listing's
// 25/-10 turn, 9 s a half turn); along a route that bends it re-aligns every second, and on the wide
// worlds a trip to the charger spent 23-47 s of its 105-112 s turning on the spot (suspend/resume,
// wide world 139). A heading off by less than arcWithin degrees is now taken in an arc instead,
// the outer wheel at travel speed and the inner at arcInner of it, until the heading is within
// arcDone; a larger turn, and any turn near the point headed for (an arc would circle it), in the
// storage area or at the charger, is heading's turn on the spot.
// Parameters:
arcWithin(45).   // degrees off: a smaller turn is taken in an arc
arcDone(2).      // degrees off where the arc ends and the robot goes straight on
arcInner(0.3).   // the inner wheel's share of the outer wheel's speed in the arc
arcClear(0.15).  // m: nearer the point headed for than this the robot turns on the spot
// Reads: travelling, insideArea (delivery), searching (sweep), avoiding (avoidance), atCharger
// (recharge-trip), aim(X, Z), headingOff(G), desiredOnTheRight, speedOnTheWay(V) (heading).
// Needs: heading (its !balance and !cruise). Include it after recharge.asl (@stayOnCharger comes
// first) and before delivery (heading's +!balance plans come after these).

arcTurn(G) :- (travelling | searching) & not insideArea & not avoiding & not atCharger & headingOff(G) & arcWithin(A) & G < A
    & aim(Ax, Az) & location(X, _, Z) & arcClear(C) & (X - Ax) * (X - Ax) + (Z - Az) * (Z - Az) > C * C.

@arcEnded +!balance : arcTurn(G) & arcDone(E) & G <= E <- -~around; +firstTime; !cruise.
@arcRight
+!balance : arcTurn(_) & desiredOnTheRight & speedOnTheWay(V) & arcInner(F)
    <- setSpeeds(V, V * F); .wait(20); !balance.
@arcLeft +!balance : arcTurn(_) & speedOnTheWay(V) & arcInner(F) <- setSpeeds(V * F, V); .wait(20); !balance.
