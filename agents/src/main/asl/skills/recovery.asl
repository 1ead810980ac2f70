// Skill: recovery, not in the thesis: bounded waits, escapes, an obstacle still in sight.
// The thesis waits for obstacle(false) without a bound; a robot wedged between boxes waited for
// ever. Here every such wait (!clear) ends, after avoidTimeout, with an escape (back off, turn a
// random angle). See also progress-watch.asl (the middleware's "stuck" percept).
// Parameters:
avoidTimeout(3000).   // ms an obstacle may stay before the escape
escapeBack(1200).     // ms of backing off in an escape
// Reads: maxSpeed(M); picked(true) (picking). Include it after far sight, before sweep and random walk.

// the obstacle may already be gone (then no +obstacle(false) would come)
@clearAlready +!clear : obstacle(false).
@clearWait +!clear : avoidTimeout(T) <- .wait("+obstacle(false)", T).
@clearTimedOut -!clear <- println("Obstacle does not clear: escaping"); !escape.

// back off, turn a random angle, go on
@escapeBackOff
+!escape : maxSpeed(M) & escapeBack(B)
    <- setSpeeds(-M / 2, -M / 2); .wait(B); .random(R); W = 700 + R * 1500;
       if (R < 0.5) { setSpeeds(M / 2, -M / 2) } else { setSpeeds(-M / 2, M / 2) }; .wait(W); forward.

// an obstacle still seen when avoiding ended raises no new event: avoid it now, inside the move
// (avoidingInMove while it runs: avoidance's @moveAfterCutOff)
@moveAvoidStill +!move(N) : obstacle(true) & delta(D) & not picked(true) <- +avoiding; +avoidingInMove; stop; !avoid(D); -avoidingInMove.
