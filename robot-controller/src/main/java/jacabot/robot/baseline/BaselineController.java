package jacabot.robot.baseline;

import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import java.util.Random;
import java.util.function.Consumer;

/**
 * A procedural controller in the style of the thesis' C programs (Chapter 4, "C" sections): a main
 * loop that polls the devices once per control step and decides with {@code if} tests, and
 * routines that block by stepping the world themselves, as C functions call
 * {@code wb_robot_step(TIME_STEP)} inside their own loops. No events, no agent, no artifact.
 *
 * <p>{@link #step()} plays {@code wb_robot_step}: when the run's simulated time is over it unwinds
 * the whole controller (as Webots ends a controller process), so routines need no exit code.
 */
public abstract class BaselineController {
    /** Thrown by {@link #step()} at the end of the run; stackless, caught only by {@link #runFor}. */
    private static final class RunOver extends RuntimeException {
        RunOver() {
            super("simulated time is over", null, false, false);
        }
    }

    protected final SimWorld world;
    protected final Robot robot;
    /** The random motion's generator, seeded from the run's seed. */
    protected final Random random;
    /** Forward, turn and half speeds in wheel units. */
    protected final double maxSpeed;
    private final Consumer<String> console;
    private long endMs = Long.MAX_VALUE;
    /** What {@link #step()} does once the run is not over: the world's step, or a team's turn ({@link TeamBaseline}). */
    private Runnable stepper;

    /** @param console where {@link #print} lines go (the C programs' printf), e.g. a run recorder's note */
    protected BaselineController(SimWorld world, String robotName, long seed, Consumer<String> console) {
        this.world = world;
        this.robot = world.robot(robotName);
        this.random = new Random(seed);
        this.maxSpeed = robot.getWheels().getMaxSpeed();
        this.console = console;
        this.stepper = world::step;
    }

    /** Steps by {@code next} instead of stepping the world: a team's controllers step it together. */
    final void stepWith(Runnable next) {
        this.stepper = next;
    }

    /** Enables the devices the controller reads (first readings one control step later). */
    protected abstract void setUp();

    /** One pass of the main loop: read, test, act; may block in a routine that steps the world. */
    protected abstract void controlStep();

    /** Runs the controller for {@code seconds} of simulated time from now, then returns. */
    public final void runFor(double seconds) {
        endMs = world.timeMs() + Math.round(seconds * 1000);
        try {
            setUp();
            while (true) {
                step();
                controlStep();
            }
        } catch (RunOver over) {
            robot.setSpeeds(0, 0);
        }
    }

    /** Advances one control step, as {@code wb_robot_step(TIME_STEP)}. */
    protected final void step() {
        if (world.timeMs() >= endMs) {
            throw new RunOver();
        }
        stepper.run();
    }

    /** Steps for {@code seconds} of simulated time, keeping the current commands. */
    protected final void pause(double seconds) {
        for (long n = steps(seconds); n > 0; n--) {
            step();
        }
    }

    /** {@return the number of control steps in {@code seconds}, at least 1} */
    protected final long steps(double seconds) {
        return Math.max(1, Math.round(seconds * 1000 / world.controlStep()));
    }

    /** {@return the simulated time now, ms} */
    protected final long now() {
        return world.timeMs();
    }

    /** {@return the seconds a spin at ±{@code speed} takes to turn {@code degrees}, from the model's wheels} */
    protected final double spinSeconds(double degrees, double speed) {
        double degreesPerSecond = Math.toDegrees(2 * speed * robot.model().speedUnit() / robot.model().axleLength());
        return degrees / degreesPerSecond;
    }

    /** Stops the wheels and idles to the end of the run (the C programs' {@code break} out of the main loop). */
    protected final void halt() {
        robot.setSpeeds(0, 0);
        while (true) {
            step();
        }
    }

    /** A console line, as the C programs' printf. */
    protected final void print(String line) {
        console.accept(line);
    }
}
