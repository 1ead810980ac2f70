package jacabot.robot.baseline;

import jacabot.sim.SimWorld;
import jacabot.sim.device.DifferentialWheels;
import jacabot.sim.device.DistanceSensor;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashSet;
import java.util.Set;
import java.util.function.Consumer;

/**
 * Experiment 1 as a careful C programmer would write it with the default agent's capabilities
 * (skills/coverage.asl and recovery.asl, the same figures), for the two-sensor MyBot without GPS:
 * straight legs at full speed of 5 to 20 s, cut short after 2 s over floor already crossed; turns on
 * the spot towards the floor not crossed yet, by dead reckoning from the wheel speeds; an obstacle
 * turned away from until clear (3 s at most, then an escape), then an arc away from it for 300 ms;
 * five obstacles within 8 s (a corner, a gap between boxes) end in an escape; closer obstacle levels
 * in arenas of 2 m² or more, and in arenas of 5 m² or more a left-right difference that signals an
 * obstacle only over 200 and clears under 190 (coverage.asl's deltaLevels).
 */
public final class EqualObstacleAvoidanceBaseline extends BaselineController {
    static final long TRAP_WINDOW = 8_000, STALE_LIMIT = 2_000, VEER = 300, NO_TURN_AFTER_OBSTACLE = 2_000;
    static final int TRAP_COUNT = 5;
    static final double CELL = 0.1, HORIZON = 0.6, CLEAR_PATIENCE = 3, CLOSE_AREA = 2;
    /** coverage.asl's looseArea and deltaLevels: in a big arena the long turns of a tight difference cost coverage. */
    static final double LOOSE_AREA = 5, LOOSE_DELTA = 200, LOOSE_CLEAR = 190;

    private final double obstacle, safe, delta;
    /** The left-right difference an obstacle must fall under to be clear (infinite: both sensors safe is enough). */
    private final double deltaClear;
    private final Set<Long> crossed = new HashSet<>();
    private final Deque<Long> obstacles = new ArrayDeque<>();
    private DistanceSensor left, right;
    private double x, z, heading; // dead reckoning from the start: metres, radians
    private long legEnds, staleSince = -1, current = Long.MIN_VALUE;
    private boolean overOld;

    public EqualObstacleAvoidanceBaseline(SimWorld world, String robotName, long seed, Consumer<String> console) {
        super(world, robotName, seed, console);
        var arena = world.spec().arena();
        double area = arena.width() * arena.depth();
        boolean close = area >= CLOSE_AREA, loose = area >= LOOSE_AREA;
        obstacle = close ? 480 : 350;
        safe = close ? 300 : 200;
        delta = loose ? LOOSE_DELTA : close ? 150 : 100;
        deltaClear = loose ? LOOSE_CLEAR : Double.POSITIVE_INFINITY;
    }

    @Override
    protected void setUp() {
        left = robot.getDistanceSensor("left");
        right = robot.getDistanceSensor("right");
        left.enable(world.controlStep());
        right.enable(world.controlStep());
    }

    @Override
    protected void controlStep() {
        reckon();
        double l = left.getValue(), r = right.getValue();
        if (signalled(l, r)) {
            avoid(l - r);
        } else if (now() >= legEnds || stale()) {
            nextMove();
        }
    }

    /** Turns away until clear, then an arc away; a trap or a wait that does not end: escape. */
    private void avoid(double d) {
        robot.setSpeeds(0, 0);
        long t = now();
        obstacles.addFirst(t);
        while (obstacles.peekLast() < t - TRAP_WINDOW) {
            obstacles.removeLast();
        }
        if (obstacles.size() >= TRAP_COUNT) {
            print("Trapped: turning away");
            obstacles.clear();
            escape();
            return;
        }
        if (Math.abs(d) <= delta) {
            robot.setSpeeds(-maxSpeed / 2, -maxSpeed / 2);
            tick(0.5);
            robot.setSpeeds(maxSpeed, -maxSpeed);
            tick(spinSeconds(180, maxSpeed));
        }
        int side = d > 0 ? 1 : -1; // obstacle on the left: turn right
        robot.setSpeeds(side * maxSpeed, -side * maxSpeed);
        long since = now();
        while (!clear(left.getValue(), right.getValue())) {
            if (now() - since > CLEAR_PATIENCE * 1000) {
                print("Obstacle does not clear: escaping");
                escape();
                return;
            }
            tick(0);
        }
        robot.setSpeeds(side > 0 ? maxSpeed : maxSpeed / 3, side > 0 ? maxSpeed / 3 : maxSpeed);
        tick(VEER / 1000.0);
        leg(now() + NO_TURN_AFTER_OBSTACLE);
    }

    /** {@return whether the front readings signal an obstacle: a difference over the limit or a sensor past the warning, not clear} */
    boolean signalled(double l, double r) {
        return (Math.abs(l - r) > delta || l > obstacle || r > obstacle) && !clear(l, r);
    }

    /** {@return whether both front sensors are under the safe level and their difference within the clear one} */
    boolean clear(double l, double r) {
        return l < safe && r < safe && Math.abs(l - r) <= deltaClear;
    }

    /** A step back of 1.5 cm, then a random turn on the spot. */
    private void escape() {
        robot.setSpeeds(-maxSpeed, -maxSpeed);
        tick(0.15);
        robot.setSpeeds(maxSpeed, -maxSpeed);
        tick((1.8 + random.nextDouble() * 1.8) / 2);
        leg(now() + 5_000);
    }

    /** A straight leg, or (seven times of ten, not just after an obstacle) a turn towards new floor first. */
    private void nextMove() {
        boolean justAvoided = !obstacles.isEmpty() && now() - obstacles.peekFirst() < NO_TURN_AFTER_OBSTACLE;
        if (random.nextDouble() > 0.3 && !justAvoided) {
            double best = heading, most = -1;
            for (int k = 0; k < 12; k++) {
                double h = heading + k * Math.PI / 6;
                int fresh = 0;
                for (double s = CELL; s <= HORIZON; s += CELL) {
                    fresh += crossed.contains(cell(x + s * Math.cos(h), z + s * Math.sin(h))) ? 0 : 1;
                }
                if (fresh > most) {
                    most = fresh;
                    best = h;
                }
            }
            double turn = Math.toDegrees(Math.IEEEremainder(best - heading, 2 * Math.PI));
            robot.setSpeeds(turn > 0 ? maxSpeed : -maxSpeed, turn > 0 ? -maxSpeed : maxSpeed);
            tick(spinSeconds(Math.abs(turn), maxSpeed));
        }
        leg(now() + 5_000 + Math.round(random.nextDouble() * 15_000));
    }

    private void leg(long until) {
        robot.setSpeeds(maxSpeed, maxSpeed);
        legEnds = until;
        staleSince = -1;
    }

    /** {@return whether the leg has gone {@link #STALE_LIMIT} over floor crossed before} */
    private boolean stale() {
        long c = cell(x, z);
        if (c != current) {
            current = c;
            overOld = !crossed.add(c);
        }
        if (!overOld) {
            staleSince = -1;
            return false;
        }
        if (staleSince < 0) {
            staleSince = now();
        }
        return now() - staleSince >= STALE_LIMIT;
    }

    /** Steps for {@code seconds} (one step at least), keeping the dead reckoning. */
    private void tick(double seconds) {
        for (long n = steps(seconds); n > 0; n--) {
            step();
            reckon();
        }
    }

    /** Dead reckoning over the last control step from the wheel speeds (turning right = heading up, as the compass). */
    private void reckon() {
        DifferentialWheels w = robot.getWheels();
        double dt = world.controlStep() / 1000.0;
        double vl = w.getLeftSpeed() * w.getSpeedUnit(), vr = w.getRightSpeed() * w.getSpeedUnit();
        heading += (vl - vr) / w.getAxleLength() * dt;
        x += (vl + vr) / 2 * Math.cos(heading) * dt;
        z += (vl + vr) / 2 * Math.sin(heading) * dt;
    }

    private static long cell(double x, double z) {
        return (long) Math.floor(x / CELL) * 1_000_003L + (long) Math.floor(z / CELL);
    }
}
