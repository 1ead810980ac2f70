package jacabot.robot.baseline;
import jacabot.robot.Experiment;

import jacabot.sim.SimWorld;
import jacabot.sim.device.DistanceSensor;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * Experiment 1 (thesis Chapter 4 §1) the C way, for the two-sensor MyBot: wander at random; an
 * obstacle is a left-right difference over 100 or a value over 350; turn away from its side (back
 * off and turn around when it is central) until both sensors are safe, under 200; wander again.
 *
 * <p>Fixed from the C {@code avoid()} listing (§1.2): it reads a central sensor MyBot does not have,
 * and stops turning when values fall under 350 rather than under the safe level 200 the strategy
 * (§1.1) and the middleware use; the central case of the Jason {@code !avoid(0)} plan is added.
 */
public final class ObstacleAvoidanceBaseline extends BaselineController {
    static final double OBSTACLE = 350, SAFE = 200, DELTA = 100;
    /** How long the robot backs off from a central obstacle, seconds. */
    static final double BACK_OFF = 0.5;

    private DistanceSensor left, right;
    private final RandomMotion motion;

    public ObstacleAvoidanceBaseline(SimWorld world, String robotName, long seed, Consumer<String> console) {
        super(world, robotName, seed, console);
        this.motion = new RandomMotion(robot, random, maxSpeed / 2);
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
        double l = left.getValue(), r = right.getValue();
        double delta = l - r;
        // As the middleware (§1.2), a difference over 100 counts only while a sensor is not safe.
        if ((delta > DELTA || delta < -DELTA || l > OBSTACLE || r > OBSTACLE) && !(l < SAFE && r < SAFE)) {
            avoid(delta);
            motion.resume(now(), 1000);
        } else {
            motion.poll(now());
        }
    }

    /** Turns away from the obstacle until both sensors are safe (C {@code avoid(value)}). */
    private void avoid(double delta) {
        print(String.format(Locale.ROOT, "obstacle: %.0f", delta));
        if (delta >= -DELTA && delta <= DELTA) {
            print("central obstacle");
            robot.setSpeeds(-maxSpeed / 2, -maxSpeed / 2);
            pause(BACK_OFF);
            robot.setSpeeds(maxSpeed / 2, -maxSpeed / 2);
            pause(spinSeconds(180, maxSpeed / 2));
        } else if (delta < 0) {
            robot.setSpeeds(-maxSpeed / 2, maxSpeed / 2);
        } else {
            robot.setSpeeds(maxSpeed / 2, -maxSpeed / 2);
        }
        while (!(left.getValue() < SAFE && right.getValue() < SAFE)) {
            step();
        }
    }
}
