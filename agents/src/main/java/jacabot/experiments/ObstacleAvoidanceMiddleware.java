package jacabot.experiments;

import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import java.util.ArrayDeque;

/**
 * Experiment 1's middleware (thesis Chapter 4 §1.2): {@code leftSensor}, {@code rightSensor},
 * {@code delta} and {@code obstacle(true|false)}, computed as the thesis' {@code servingLoop}:
 * an obstacle when the left-right difference exceeds {@value #DELTA_LIMIT} or a sensor exceeds
 * {@value #WARNING}; clear again when both are under {@value #SAFE} and the difference is under half
 * the limit. That hysteresis is ours: the thesis' loop clears the obstacle as soon as both sensors
 * are under {@value #SAFE}, so a wall seen at a slant (difference just over the limit, both
 * sensors under {@value #SAFE}) set and cleared it on alternate readings and the robot stuttered
 * along walls, one stop and a few degrees of turn every 120 ms.
 */
public class ObstacleAvoidanceMiddleware extends MiddlewareArtifact {
    static final double DELTA_LIMIT = 100;
    static final double WARNING = 350;
    static final double SAFE = 200;
    /** Where an obstacle is marked on the exploration map, metres from the robot's centre. */
    static final double OBSTACLE_RANGE = 0.13;
    /** With delta-based detection off, only the warning threshold counts (thesis: deltaBased(false)). */
    private boolean deltaBased = true;

    @Override
    protected void defineProperties() {
        defineObsProperty("leftSensor", 0.0);
        defineObsProperty("rightSensor", 0.0);
        defineObsProperty("delta", 0.0);
        defineObsProperty("obstacle", false);
    }

    /** The front sensors' levels for obstacle(true) and for clear again (default {@value #WARNING}, {@value #SAFE}). */
    private double warning = WARNING, safe = SAFE, deltaLimit = DELTA_LIMIT;
    /** The left-right difference under which an obstacle is clear again (NaN: half the limit; not in the thesis). */
    private double deltaClear = Double.NaN;

    /** Sets the levels (the agent's beliefs, not Java constants; not in the thesis); the warning must exceed the safe level. */
    @OPERATION
    void obstacleLevels(double warningLevel, double safeLevel) {
        if (!(warningLevel > safeLevel) || !(safeLevel > 0)) {
            failed("obstacleLevels(Warning, Safe) needs Warning > Safe > 0, got " + warningLevel + ", " + safeLevel);
            return;
        }
        warning = warningLevel;
        safe = safeLevel;
    }

    /** Sets the left-right difference that signals an obstacle (default {@value #DELTA_LIMIT}); it must be positive. */
    @OPERATION
    void deltaLimit(double limit) {
        if (positive("deltaLimit(Limit)", limit)) {
            deltaLimit = limit;
        }
    }

    /**
     * Sets the difference under which an obstacle is clear again, apart from the one that signals it
     * (default half of {@code deltaLimit}); it must be positive.
     */
    @OPERATION
    void deltaClear(double level) {
        if (positive("deltaClear(Level)", level)) {
            deltaClear = level;
        }
    }

    /** {@return whether a level is positive}; the operation fails, naming it, when it is not */
    private boolean positive(String operation, double level) {
        if (level > 0) {
            return true;
        }
        failed(operation + " needs a level > 0, got " + level);
        return false;
    }

    @OPERATION
    void deltaBased(boolean on) {
        deltaBased = on;
    }

    /** The distance sensors that play left and right for this robot. */
    protected SensorKind leftKind() {
        return SensorKind.LEFT_DISTANCE;
    }

    protected SensorKind rightKind() {
        return SensorKind.RIGHT_DISTANCE;
    }

    /** Dead reckoning and the floor crossed (not in the thesis), once the agent gave the wheel geometry. */
    private ExplorationMap map;

    /** Starts dead reckoning from the wheel speeds: metres per second of a speed unit, axle length in metres. */
    @OPERATION
    void odometry(double speedUnit, double axleLength) {
        map = new ExplorationMap(speedUnit, axleLength);
    }

    /**
     * How far ahead, in metres, {@code exploreTurn} counts the floor not crossed yet (default 3 m).
     * Fails before {@code odometry} or under 0.1 m.
     */
    @OPERATION
    void exploreHorizon(double metres) {
        if (map == null || !(metres >= ExplorationMap.CELL)) {
            failed("exploreHorizon needs odometry(SpeedUnit, AxleLength) first and at least " + ExplorationMap.CELL + " m, got " + metres);
            return;
        }
        map.horizon(metres);
    }

    /**
     * The turn on the spot towards the most floor not crossed yet (not in the thesis): {@code side} "left" or
     * "right", and how long to turn at wheel speeds ±{@code speed}. Fails before {@code odometry}.
     */
    @OPERATION
    void exploreTurn(double speed, OpFeedbackParam<String> side, OpFeedbackParam<Double> ms) {
        if (map == null || !(speed > 0)) {
            failed("exploreTurn needs odometry(SpeedUnit, AxleLength) first and a positive speed");
            return;
        }
        double turn = map.bestTurn();
        side.set(turn >= 0 ? "left" : "right");
        ms.set((double) map.turnMillis(turn, speed));
    }

    /**
     * How long the robot has gone over floor already crossed (not in the thesis), in ms: a straight leg over
     * old ground is cut short. Fails before {@code odometry}.
     */
    @OPERATION
    void staleTime(OpFeedbackParam<Double> ms) {
        if (map == null) {
            failed("staleTime needs odometry(SpeedUnit, AxleLength) first");
            return;
        }
        ms.set((double) map.staleMillis(simTimeMs()));
    }

    /**
     * How many cells the robot crossed for the first time in the last {@code windowMs} ms (not in the
     * thesis): a rate of new floor that falls tells the agent its random walk covers old ground. Fails
     * before {@code odometry}.
     */
    @OPERATION
    void freshCells(double windowMs, OpFeedbackParam<Double> cells) {
        if (map == null) {
            failed("freshCells needs odometry(SpeedUnit, AxleLength) first");
            return;
        }
        cells.set((double) map.freshCellsSince(simTimeMs() - Math.round(windowMs)));
    }

    /**
     * The turn on the spot towards the way to the nearest frontier (not in the thesis,
     * {@code ExplorationMap.frontierWaypoint}): {@code side} "left", "right" or "none" (no frontier),
     * how long to turn at wheel speeds ±{@code speed}, and how far the waypoint is then, in metres.
     * Fails before {@code odometry}.
     */
    @OPERATION
    void frontierTurn(double speed, OpFeedbackParam<String> side, OpFeedbackParam<Double> ms, OpFeedbackParam<Double> metres) {
        if (map == null || !(speed > 0)) {
            failed("frontierTurn needs odometry(SpeedUnit, AxleLength) first and a positive speed");
            return;
        }
        double[] way = map.frontierWaypoint();
        if (way == null) {
            side.set("none");
            ms.set(0.0);
            metres.set(0.0);
            return;
        }
        side.set(way[0] >= 0 ? "left" : "right");
        ms.set((double) map.turnMillis(way[0], speed));
        metres.set(way[1]);
    }

    /**
     * The floor the robot's centre has crossed, in m² (its 10 cm cells, not in the thesis). Fails before
     * {@code odometry}.
     */
    @OPERATION
    void visitedArea(OpFeedbackParam<Double> squareMetres) {
        if (map == null) {
            failed("visitedArea needs odometry(SpeedUnit, AxleLength) first");
            return;
        }
        squareMetres.set(map.cellsVisited() * ExplorationMap.CELL * ExplorationMap.CELL);
    }

    /** The weakest front reading marked on the map as a wall or box (NaN: only obstacle(true) marks). */
    private double markLevel = Double.NaN;

    /**
     * Marks on the map, from now on, every wall or box a front sensor reads at {@code level} or more,
     * where the reading puts it (not in the thesis; the MyBot's sensors, {@link #rangeOf}): before,
     * only the moment an obstacle was signalled left a mark, and the floor beyond a wall seen still
     * counted as new for {@code exploreTurn}. Fails before {@code odometry} or for a level under 1.
     */
    @OPERATION
    void markWalls(double level) {
        if (map == null || !(level >= 1)) {
            failed("markWalls needs odometry(SpeedUnit, AxleLength) first and a level of at least 1, got " + level);
            return;
        }
        markLevel = level;
    }

    /**
     * The MyBot's front sensors: on the rim and looking this many degrees off the heading, and their
     * response (the world's lookup table: 480 at 5 cm from the rim, 350 at 8 cm, 200 at 12 cm, 0 at 20 cm).
     */
    static final double SENSOR_ANGLE = 20, RIM = 0.045;
    private static final double[][] RESPONSE = {{1000, 0}, {480, 0.05}, {350, 0.08}, {200, 0.12}, {0, 0.20}};

    /** {@return the distance from the rim, metres, at which the MyBot's sensor gives {@code reading}} */
    static double rangeOf(double reading) {
        for (int k = 1; k < RESPONSE.length; k++) {
            if (reading >= RESPONSE[k][0]) {
                double[] a = RESPONSE[k - 1], b = RESPONSE[k];
                return b[1] + (a[1] - b[1]) * (reading - b[0]) / (a[0] - b[0]);
            }
        }
        return RESPONSE[RESPONSE.length - 1][1];
    }

    /** Both sensors' level for a corridor, and how far the robot must drive seeing both (NaN: off). */
    private double corridorLevel = Double.NaN, corridorSpan;
    /** Where the robot was (dead reckoning) when both sensors began to read corridorLevel; NaN: not now. */
    private double walledX = Double.NaN, walledZ;

    /**
     * From now on, the observable property {@code walledIn(true)} while both front sensors have read
     * {@code level} or more for the last {@code metres} driven (not in the thesis): a wall on each
     * side for that long is a corridor or a passage, where two boxes side by side are not. Fails
     * before {@code odometry}, for a level under 1 or a negative span.
     */
    @OPERATION
    void corridorSpan(double level, double metres) {
        if (map == null || !(level >= 1) || !(metres >= 0)) {
            failed("corridorSpan needs odometry(SpeedUnit, AxleLength) first, a level of at least 1 and a span of 0 m or more, got "
                    + level + ", " + metres);
            return;
        }
        corridorLevel = level;
        corridorSpan = metres;
        if (!hasObsProperty("walledIn")) {
            defineObsProperty("walledIn", false);
        }
    }

    private void trackCorridor(double left, double right) {
        if (Double.isNaN(corridorLevel)) {
            return;
        }
        boolean both = left >= corridorLevel && right >= corridorLevel;
        if (!both) {
            walledX = Double.NaN;
        } else if (Double.isNaN(walledX)) {
            walledX = map.x();
            walledZ = map.z();
        }
        boolean walled = both && Math.hypot(map.x() - walledX, map.z() - walledZ) >= corridorSpan;
        if (walled != getObsProperty("walledIn").booleanValue()) {
            getObsProperty("walledIn").updateValue(walled);
            markTrigger();
        }
    }

    /** The flank watch's level, window, margin and reach (NaN level: off), and the points it remembers: {ms, x, z}. */
    private double flankLevel = Double.NaN, flankWindowMs, flankMargin, flankReach;
    private final ArrayDeque<double[]> flankPoints = new ArrayDeque<>();
    /** The wheel speeds in effect (the last wheel reading). */
    private double wheelLeft, wheelRight;

    /**
     * From now on, remembers for {@code windowMs} ms where each front sensor read {@code level} or
     * more (dead reckoning, where the reading puts the point, as {@code markWalls} does), and keeps
     * the observable property {@code flankAhead(Side)} (not in the thesis): "left" or "right" while
     * the robot drives forward and a remembered point lies in the strip its body sweeps
     * ({@code margin} m wider than the body on each side), ahead of its centre and at most
     * {@code reach} m beyond its rim, the side of the closest; else "none". A box beside the robot,
     * out of the front sensors' sight once it has passed their cones, is what the flank touched after
     * an avoidance turn. Fails before {@code odometry}, for a level under 1, a window under 40 ms, or
     * a negative margin or reach.
     */
    @OPERATION
    void flankWatch(double level, double windowMs, double margin, double reach) {
        if (map == null || !(level >= 1) || !(windowMs >= 40) || !(margin >= 0) || !(reach >= 0)) {
            failed("flankWatch needs odometry(SpeedUnit, AxleLength) first, a level of at least 1, a window of 40 ms or more"
                    + " and a margin and reach of 0 m or more, got " + level + ", " + windowMs + ", " + margin + ", " + reach);
            return;
        }
        flankLevel = level;
        flankWindowMs = windowMs;
        flankMargin = margin;
        flankReach = reach;
        if (!hasObsProperty("flankAhead")) {
            defineObsProperty("flankAhead", "none");
        }
    }

    /**
     * The smallest turn on the spot after which driving forward meets none of the flank watch's
     * points (not in the thesis): {@code side} "left" or "right" (away from the closest point first
     * on a tie) and how long to turn at wheel speeds ±{@code speed}; "none" when no turn of up to a
     * half turn clears them. Fails before {@code flankWatch}.
     */
    @OPERATION
    void flankTurn(double speed, OpFeedbackParam<String> side, OpFeedbackParam<Double> ms) {
        if (Double.isNaN(flankLevel) || !(speed > 0)) {
            failed("flankTurn needs flankWatch(Level, WindowMs, Margin, Reach) first and a positive speed");
            return;
        }
        forgetFlankPoints();
        int away = -blockedSide(0);
        for (int deg = 5; deg <= 180; deg += 5) {
            for (int sign : new int[] {away == 0 ? 1 : away, away == 0 ? -1 : -away}) {
                if (blockedSide(Math.toRadians(sign * deg)) == 0) {
                    side.set(sign > 0 ? "left" : "right");
                    ms.set((double) map.turnMillis(deg, speed));
                    return;
                }
            }
        }
        side.set("none");
        ms.set(0.0);
    }

    private void forgetFlankPoints() {
        long now = simTimeMs();
        while (!flankPoints.isEmpty() && now - flankPoints.peekFirst()[0] > flankWindowMs) {
            flankPoints.pollFirst();
        }
    }

    /** {@return 1 (left), -1 (right) or 0: the side of the closest remembered point in the path after a turn of {@code turn} radians (left positive)} */
    private int blockedSide(double turn) {
        double h = Math.toRadians(map.headingDegrees()) + turn, c = Math.cos(h), s = Math.sin(h);
        double best = Double.POSITIVE_INFINITY;
        int side = 0;
        for (double[] p : flankPoints) {
            double dx = p[1] - map.x(), dz = p[2] - map.z();
            double ahead = dx * c + dz * s, left = -dx * s + dz * c, d = Math.hypot(ahead, left);
            if (ahead > 0 && Math.abs(left) < RIM + flankMargin && d <= RIM + flankReach && d < best) {
                best = d;
                side = left >= 0 ? 1 : -1;
            }
        }
        return side;
    }

    /**
     * The MyBot's sensor casts three rays, on its axis and {@value #RAY_SPREAD} degrees either side,
     * the outer ones weighing {@value #OUTER_SHARE} of the reading: a box seen by the outer ray alone
     * reads that share of what the ray meets.
     */
    static final double RAY_SPREAD = 15, OUTER_SHARE = 0.3045;
    /** Each sensor's last outer-ray point not yet committed: {ms, x, z, reading, previous reading, outer ray alone (1) or not (0)}; null: none. */
    private double[] leftGlimpse, rightGlimpse;
    /** Each sensor's previous reading, and whether its outer ray alone sees the box (a drop since the last rise). */
    private double leftPrevious, rightPrevious;
    private boolean leftOuter, rightOuter;

    /**
     * The last glimpse of a box leaving a sensor's cone outwards (the robot driving on, or turning
     * away from that side), read as the outer ray's alone: the point that share of the reading puts
     * it at, then at the flank, out of the front sensors' sight. A glimpse is kept once the reading
     * falls to a third or under the level.
     */
    private double[] glimpse(double reading, double bearing, double[] last, boolean outer) {
        if (map == null || Double.isNaN(flankLevel)) {
            return null;
        }
        double side = Math.signum(bearing);
        boolean turningToward = side * (wheelRight - wheelLeft) > 0 && !(wheelLeft > 0 && wheelRight > 0);
        if (last != null && (reading < last[3] / 3 || reading < flankLevel) && !turningToward && outer) {
            flankPoints.addLast(new double[] {last[0], last[1], last[2]});
        }
        if (reading < flankLevel || reading > OUTER_SHARE * 1000) {
            return null;
        }
        double h = Math.toRadians(map.headingDegrees()), m = h + Math.toRadians(bearing), a = m + Math.toRadians(side * RAY_SPREAD);
        double d = rangeOf(reading / OUTER_SHARE);
        return new double[] {simTimeMs(), map.x() + RIM * Math.cos(m) + d * Math.cos(a), map.z() + RIM * Math.sin(m) + d * Math.sin(a), reading};
    }

    /** {@return whether the outer ray alone sees the box now: a drop to under 0.6 of the reading before (the axis ray left: with the three rays at one distance, 0.44; the inner ray, 0.70) since the last rise, in the outer ray's range} */
    private static boolean outerAlone(boolean was, double previous, double reading) {
        if (reading > OUTER_SHARE * 1000 || reading > previous * 1.3) {
            return false;
        }
        return was || reading < previous * 0.6;
    }

    private void trackFlank() {
        if (Double.isNaN(flankLevel)) {
            return;
        }
        forgetFlankPoints();
        int side = wheelLeft > 0 && wheelRight > 0 ? blockedSide(0) : 0;
        String now = side > 0 ? "left" : side < 0 ? "right" : "none";
        if (!now.equals(getObsProperty("flankAhead").stringValue())) {
            getObsProperty("flankAhead").updateValue(now);
            markTrigger();
        }
    }

    private void markReading(double reading, double bearing) {
        if (map != null && reading >= markLevel) {
            map.obstacle(bearing, RIM + rangeOf(Math.min(reading, 1000)));
        }
    }

    @Override
    protected void onReading(SensorInfo info, SensorKind kind) {
        if (kind == SensorKind.WHEEL_SPEEDS && map != null) {
            double[] w = info.getDoubleValues();
            if (w.length >= 2) {
                map.wheels(simTimeMs(), w[0], w[1]);
                wheelLeft = w[0];
                wheelRight = w[1];
            }
        }
        if (stopDistance) {
            return;
        }
        if (kind == leftKind()) {
            getObsProperty("leftSensor").updateValue(info.getVal());
            markReading(info.getVal(), SENSOR_ANGLE);
            double left = info.getVal();
            boolean outer = leftOuter;
            leftOuter = outerAlone(leftOuter, leftPrevious, left);
            leftPrevious = left;
            leftGlimpse = glimpse(left, SENSOR_ANGLE, leftGlimpse, outer);
        } else if (kind == rightKind()) {
            // the right reading closes a left/right pair: decide as the thesis does
            double right = info.getVal();
            markReading(right, -SENSOR_ANGLE);
            boolean outer = rightOuter;
            rightOuter = outerAlone(rightOuter, rightPrevious, right);
            rightPrevious = right;
            rightGlimpse = glimpse(right, -SENSOR_ANGLE, rightGlimpse, outer);
            double left = getObsProperty("leftSensor").doubleValue();
            getObsProperty("rightSensor").updateValue(right);
            trackCorridor(left, right);
            trackFlank();
            double delta = Math.round(left - right);
            getObsProperty("delta").updateValue(delta);
            boolean obstacle = getObsProperty("obstacle").booleanValue();
            if (deltaBased && Math.abs(delta) > deltaLimit || right > warning || left > warning) {
                obstacle = true;
            } else if (right < safe && left < safe && Math.abs(delta) <= (Double.isNaN(deltaClear) ? deltaLimit / 2 : deltaClear) && clearAhead()) {
                obstacle = false;
            }
            if (obstacle != getObsProperty("obstacle").booleanValue()) {
                if (obstacle && map != null) {
                    map.obstacle(delta > 0 ? 20 : delta < 0 ? -20 : 0, OBSTACLE_RANGE);
                }
                getObsProperty("obstacle").updateValue(obstacle);
                markTrigger();
            }
        }
    }

    /** Subclasses with a central sensor also need it safe before the obstacle is gone. */
    protected boolean clearAhead() {
        return true;
    }
}
