package jacabot.experiments;

import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;

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
            }
        }
        if (stopDistance) {
            return;
        }
        if (kind == leftKind()) {
            getObsProperty("leftSensor").updateValue(info.getVal());
            markReading(info.getVal(), SENSOR_ANGLE);
        } else if (kind == rightKind()) {
            // the right reading closes a left/right pair: decide as the thesis does
            double right = info.getVal();
            markReading(right, -SENSOR_ANGLE);
            double left = getObsProperty("leftSensor").doubleValue();
            getObsProperty("rightSensor").updateValue(right);
            trackCorridor(left, right);
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
