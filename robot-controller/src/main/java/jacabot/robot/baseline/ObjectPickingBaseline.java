package jacabot.robot.baseline;
import jacabot.robot.Experiment;

import jacabot.sim.SimWorld;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.device.Section;
import java.util.Locale;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * Experiment 2 (thesis Chapter 4 §2) the C way, for the Khepera: wander and avoid obstacles as in
 * experiment 1 (front-left/front-right play MyBot's left/right); when the front sensor is very
 * close (over 480) and red rules the camera's centre, stop and pick the cylinder up with time
 * limits; red on a lateral section next to a lateral obstacle makes the robot turn towards it
 * first. While carrying, a grip force out of range means the cylinder fell: stop and report.
 *
 * <p>The main loop tests the most critical condition first, as §2.2 says: the fall. Every routine
 * that blocks polls {@link #urgent()} at each step, the "test in every relevant point" of
 * Chapter 5 §1, and gives up when it holds; later experiments add their conditions there.
 *
 * <p>Fixed from the C {@code pickUp} listing (§2.2): the timeout lost 50 ms per 40 ms step and was
 * tested with {@code == 0}, so a missed grip never timed out; here simulated time is compared.
 * The Jason reach plans turn at (0, 10) for at most 3 s, about 16 degrees, too little to face a
 * cylinder seen 45 degrees aside; here the robot spins slowly until it faces it, for at most 6 s.
 */
public class ObjectPickingBaseline extends BaselineController {
    static final double OBSTACLE = 350, VERY_CLOSE = 480, SAFE = 200, DELTA = 100;
    /** The gripper's limits, seconds (Appendix B: caught within 5 s, picked within 3.5 s). */
    static final double GRIP_TIMEOUT = 5, ARM_TIMEOUT = 3.5;
    /** How long the robot turns towards, then creeps up to, a lateral cylinder, seconds. */
    static final double REACH_TURN = 6, REACH_CREEP = 15;
    /** Backing off before an avoiding turn (Appendix B {@code backward}), seconds. */
    static final double BACK_OFF = 0.3;

    protected KheperaIo io;
    protected final RandomMotion motion;
    /** Whether a cylinder is held and lifted (the middleware's {@code picked}). */
    protected boolean picked;
    /** The default agent's strategies, for the equal-capability baseline; null in the thesis' programs. */
    protected EqualCapabilities equal;

    public ObjectPickingBaseline(SimWorld world, String robotName, long seed, Consumer<String> console) {
        super(world, robotName, seed, console);
        this.motion = new RandomMotion(robot, random, maxSpeed / 2);
    }

    @Override
    protected void setUp() {
        io = new KheperaIo(robot, world.controlStep());
    }

    @Override
    protected void controlStep() {
        checkFallen();
        double fl = io.frontLeft.getValue(), f = io.front.getValue(), fr = io.frontRight.getValue();
        double delta = fl - fr;
        if (f > VERY_CLOSE) {
            if (mayPick() && io.isRed(Section.CENTRE)) {
                print("Cylinder found");
                pickUp();
            } else {
                avoid(delta);
            }
        } else if (mayPick() && io.isRed(Section.LEFT)) {
            reachLateral(-1);
        } else if (mayPick() && io.isRed(Section.RIGHT)) {
            reachLateral(1);
        } else if (obstacleAhead()) {
            avoid(delta);
        } else {
            wander();
        }
    }

    /**
     * Gives this program the default agent's capabilities ({@link EqualCapabilities}): the
     * equal-capability baseline of the experiment. {@return this}
     */
    public final ObjectPickingBaseline withEqualCapabilities() {
        AreaSpec storage = world.spec().storage();
        equal = new EqualCapabilities(this, storage, EqualCapabilities.SWEEP_AFTER);
        return this;
    }

    /** {@return whether this is the equal-capability baseline} */
    public final boolean hasEqualCapabilities() {
        return equal != null;
    }

    /** What the robot does when nothing else applies: the C programs' random motion, or far sight and search. */
    protected final void wander() {
        if (equal != null) {
            equal.wander();
        } else {
            motion.poll(now());
        }
    }

    /** {@return how long a wait for an obstacle to clear may last, seconds}: the thesis' programs wait for ever */
    private double clearPatience() {
        return equal != null ? EqualCapabilities.CLEAR_PATIENCE : Double.POSITIVE_INFINITY;
    }

    /** The escape from a wait that did not end (equal capabilities only). */
    protected final void escape() {
        if (equal != null) {
            equal.escape();
        }
    }

    /** {@return whether a wait for the front to clear that began at {@code since} ms has run out (then escaped)} */
    protected final boolean clearTimedOut(long since) {
        if (now() - since > clearPatience() * 1000) {
            escape();
            return true;
        }
        return false;
    }

    /** While carrying, a grip force out of range means the cylinder fell: stop for good (§2.2). */
    protected final void checkFallen() {
        if (picked && !io.gripping()) {
            picked = false;
            print("Cylinder has fallen. Anybody retrieve it.");
            fallen();
        }
    }

    /** After a fall: the thesis' programs stop for good; with equal capabilities, look around for it. */
    protected void fallen() {
        if (equal == null) {
            halt();
        }
        abandonPick();
        equal.lookAround();
    }

    /** {@return whether a routine must give up at once for a more important task} */
    protected boolean urgent() {
        return picked && !io.gripping();
    }

    /** {@return whether a red cylinder seen now may be picked} */
    protected boolean mayPick() {
        return !picked;
    }

    /** Called once the cylinder is held and lifted; experiment 2 wanders on carrying it. */
    protected void afterPicked() {
        motion.resume(now(), 1000);
    }

    /**
     * {@return whether the front sensors see an obstacle (the middleware's obstacle(true))}: a value
     * over 350 (480 for the front sensor, which looks for cylinders) or a left-right difference over
     * 100, unless all three are safe; the middleware's update order makes the same exception.
     */
    protected final boolean obstacleAhead() {
        double fl = io.frontLeft.getValue(), f = io.front.getValue(), fr = io.frontRight.getValue();
        return (f > VERY_CLOSE || fl > OBSTACLE || fr > OBSTACLE || Math.abs(fl - fr) > DELTA) && !safe();
    }

    /** {@return whether all three front sensors are back to safe levels} */
    protected final boolean safe() {
        return io.frontLeft.getValue() < SAFE && io.front.getValue() < SAFE && io.frontRight.getValue() < SAFE;
    }

    /**
     * Turns away from the obstacle until the front sensors are safe (C {@code avoid}, Appendix B
     * {@code !avoid(D)}): right when it is on the left (delta over 100), left when on the right,
     * backed off and turned around when central. Appendix B also backs off before a side turn; that
     * can leave the sensors safe at once, and the robot drives back into the obstacle for ever.
     * {@return false when interrupted by an urgent task}
     */
    protected boolean avoid(double delta) {
        print(String.format(Locale.ROOT, "obstacle: %.0f", delta));
        if (delta >= -DELTA && delta <= DELTA) {
            robot.setSpeeds(-maxSpeed / 2, -maxSpeed / 2);
            pause(BACK_OFF);
            turnAround();
        } else {
            spinAway(delta);
        }
        long since = now();
        while (!safe() && !clearTimedOut(since)) {
            step();
            if (urgent()) {
                return false;
            }
        }
        motion.resume(now(), 1000);
        return true;
    }

    /** Spins away from the side of the obstacle: right when delta is positive (obstacle on the left). */
    protected final void spinAway(double delta) {
        if (delta > 0) {
            robot.setSpeeds(maxSpeed / 2, -maxSpeed / 2);
        } else {
            robot.setSpeeds(-maxSpeed / 2, maxSpeed / 2);
        }
    }

    /** Spins half a turn on the spot, then keeps spinning (the middleware's {@code turnAround}). */
    protected final void turnAround() {
        robot.setSpeeds(maxSpeed / 2, -maxSpeed / 2);
        pause(spinSeconds(180, maxSpeed / 2));
    }

    /**
     * Picks up the cylinder in front (C {@code pickUp}, Appendix B {@code catching}, {@code !block},
     * {@code !pick}): open and lower, close, wait for the grip force within 5 s, raise within 3.5 s.
     * A grip that never comes means the cylinder moved: open, turn around, wander on.
     */
    protected final void pickUp() {
        robot.setSpeeds(0, 0);
        io.gripper.openGrip();
        io.gripper.armDown();
        if (!waitFor(io.gripper::isArmDown, 1.5)) {
            abandonPick();
            return;
        }
        io.gripper.closeGrip();
        if (!waitFor(io::gripping, GRIP_TIMEOUT)) {
            if (!urgent()) {
                print("Object not found");
                abandonPick();
                turnAround();
                motion.resume(now(), 1000);
            } else {
                abandonPick();
            }
            return;
        }
        io.gripper.armUp();
        if (!waitFor(io.gripper::isArmUp, ARM_TIMEOUT) || !io.gripping()) {
            print("Cylinder picking failed");
            abandonPick();
            return;
        }
        picked = true;
        print("Picking ok");
        if (equal != null) {
            equal.found();
        }
        afterPicked();
    }

    /** Opens the fingers and raises the arm, letting go of whatever they hold. */
    protected final void abandonPick() {
        io.gripper.openGrip();
        io.gripper.armUp();
    }

    /** Steps until the test holds or {@code seconds} pass; {@return whether it held} (false when urgent). */
    protected final boolean waitFor(BooleanSupplier test, double seconds) {
        return waitFor(test, seconds, true);
    }

    /** As {@link #waitFor(BooleanSupplier, double)}, deaf to urgent tasks unless {@code interruptible}. */
    protected final boolean waitFor(BooleanSupplier test, double seconds, boolean interruptible) {
        long end = now() + Math.round(seconds * 1000);
        while (!test.getAsBoolean()) {
            if (now() >= end || interruptible && urgent()) {
                return false;
            }
            step();
        }
        return true;
    }

    /**
     * A red object beside the front (Appendix B {@code cylinderLeft}/{@code cylinderRight}): spin
     * slowly towards it until red rules the centre, then creep up to it keeping it in the centre;
     * the main loop then sees it very close and picks it. Gives up after the time limits.
     *
     * <p>The trigger is the camera alone: the Khepera's front-left/front-right sensors look 35 to
     * 55 degrees aside, outside the camera's 60-degree field, so the lateral case of Chapter 4
     * §2.1 (an object next to the robot's left/right, then the red of the camera's lateral
     * sections) never happens. Red ruling a third of the image already means near: a cylinder
     * 20 cm away fills too little of it.
     */
    private void reachLateral(int side) {
        print(side < 0 ? "Left Cylinder" : "Right Cylinder");
        double slow = maxSpeed / 10;
        robot.setSpeeds(side * slow, -side * slow);
        if (!waitFor(() -> io.isRed(Section.CENTRE), REACH_TURN)) {
            print("Reach lateral cylinder failed.");
            motion.resume(now(), 1000);
            return;
        }
        long end = now() + Math.round(REACH_CREEP * 1000);
        while (!(io.front.getValue() > VERY_CLOSE)) {
            if (now() >= end || urgent()) {
                print("Reach lateral cylinder failed.");
                motion.resume(now(), 1000);
                return;
            }
            if (io.isRed(Section.CENTRE)) {
                robot.setSpeeds(2 * slow, 2 * slow);
            } else if (io.isRed(Section.LEFT)) {
                robot.setSpeeds(-slow, slow);
            } else if (io.isRed(Section.RIGHT)) {
                robot.setSpeeds(slow, -slow);
            } else {
                print("Lateral cylinder lost from sight.");
                motion.resume(now(), 1000);
                return;
            }
            step();
        }
        robot.setSpeeds(0, 0);
    }
}
