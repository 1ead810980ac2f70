package jacabot.robot.baseline;
import jacabot.robot.Experiment;

import jacabot.sim.SimWorld;
import jacabot.sim.geom.Vec2;
import jacabot.sim.world.AreaSpec;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * Experiment 3 (thesis Chapter 4 §3) the C way: as experiment 2, and once a cylinder is picked,
 * align with the compass towards the storage point computed from the GPS, go straight, avoid
 * obstacles and re-align, put the cylinder down on the point, turn around and leave the area; then
 * wander and look for the next cylinder. Without a cylinder the robot never enters the area again.
 *
 * <p>The main loop puts the new tests before experiment 2's, as §3.2 does with {@code fixingAngle}
 * and {@code delivering}: fall, delivery, going out, keeping out of the area.
 *
 * <p>Fixed from the C listings (§3.2): {@code balanceFunction} never re-read the compass (its loop
 * could not end), tested {@code !(a) & (b)} for {@code !(a & b)} and aimed at
 * {@code currentAngle + 180} without bringing it under 360; the storage test compared the robot's
 * centre with the point, but the gripper holds the cylinder {@link #HOLD} ahead of it, so here the
 * held cylinder's place is compared. After avoiding, the robot drives on for {@link #LEG} before
 * re-aligning: re-aligning at once turns it back into the obstacle (the Jason plan
 * {@code !avoid(D); forward; !computeGap; !balance} does the same), and a box on the straight path
 * then traps it. Cylinders already delivered lie on the point: when something is in the way and
 * the held cylinder is over the area anyway, the robot puts it down there.
 */
public class NavigationBaseline extends ObjectPickingBaseline {
    /** Where the gripper holds a cylinder: this far ahead of the robot's centre, metres. */
    static final double HOLD = 0.05;
    /** Aligned when the compass is within this of the desired bearing (§3.2, ±0.6), degrees. */
    static final double ALIGNED = 0.6;
    /** Re-align when the bearing to the target drifts further than this while going straight, degrees. */
    static final double DRIFT = 8;
    /** Straight driving after an avoiding turn before re-aligning, seconds. */
    static final double LEG = 2;
    /** Within this distance of the storage point the robot must carry a cylinder, metres. */
    static final double NO_ACCESS = 0.15;
    /** The Jason balancing speeds: 0.76 degrees per control step (sim-world README). */
    static final double TURN_FAST = 25, TURN_SLOW = -10;

    protected final AreaSpec storage;
    protected boolean delivering, goingOut;

    public NavigationBaseline(SimWorld world, String robotName, long seed, Consumer<String> console) {
        super(world, robotName, seed, console);
        this.storage = world.spec().storage();
        if (storage == null) {
            throw new IllegalArgumentException("world '" + world.name() + "' has no storage point");
        }
    }

    @Override
    protected void controlStep() {
        checkFallen();
        if (delivering) {
            deliver();
        } else if (goingOut) {
            if (io.distanceTo(storage.x(), storage.z()) > NO_ACCESS) {
                goingOut = false;
                print("Out of storage area");
            } else if (obstacleAhead()) {
                avoid(io.frontLeft.getValue() - io.frontRight.getValue());
            }
        } else if (!picked && headingIntoStorage()) {
            keepOut();
        } else {
            super.controlStep();
        }
    }

    /** Cylinders in or near the storage area are delivered ones: leave them there. */
    @Override
    protected boolean mayPick() {
        return !picked && !delivering && io.distanceTo(storage.x(), storage.z()) > NO_ACCESS + 0.05;
    }

    @Override
    protected void afterPicked() {
        print("Cylinder picked up: delivering");
        delivering = true;
    }

    /** Goes to the storage point, puts the cylinder down, turns around; returns early when urgent. */
    private void deliver() {
        double drop = storage.radius() - 0.015;
        if (!goTo(storage.x(), storage.z(), HOLD, 0.01, drop)) {
            return;
        }
        print(String.format(Locale.ROOT, "Storage point reached - Current pos %.3f %.3f", io.x(), io.z()));
        putDown();
        picked = false;
        delivering = false;
        robot.setSpeeds(-maxSpeed / 2, -maxSpeed / 2);
        pause(0.16);
        align(io.bearing() + 180);
        robot.setSpeeds(maxSpeed / 2, maxSpeed / 2);
        goingOut = true;
        print("Cylinder delivered!");
    }

    /** Lowers the arm, opens the fingers, raises the arm (C {@code putDown}); 2.5 s nothing interrupts. */
    private void putDown() {
        robot.setSpeeds(0, 0);
        io.gripper.armDown();
        waitFor(io.gripper::isArmDown, 1.5, false);
        io.gripper.openGrip();
        waitFor(() -> io.gripper.getGripPosition() == 0, 1, false);
        io.gripper.armUp();
        waitFor(io.gripper::isArmUp, 1.5, false);
    }

    /** {@return whether the robot, empty, is near the storage point and facing it} */
    private boolean headingIntoStorage() {
        return io.distanceTo(storage.x(), storage.z()) < NO_ACCESS
                && Math.abs(KheperaIo.gap(io.bearingTo(storage.x(), storage.z()), io.bearing())) < 90;
    }

    /** Turns its back on the storage point and drives off (Appendix B {@code noAccess}). */
    private void keepOut() {
        print("Too close to storage area!! Go away!");
        double away = io.bearingTo(storage.x(), storage.z()) + 180;
        double gap = KheperaIo.gap(away, io.bearing());
        spinAway(gap > 0 ? 1 : -1);
        while (Math.abs(KheperaIo.gap(away, io.bearing())) > 20) {
            step();
        }
        motion.resume(now(), 1500);
    }

    /**
     * Drives to a point (thesis §3.1): align with the bearing towards it, go straight, avoid and
     * re-align. Reached when the point {@code ahead} metres in front of the centre is within
     * {@code tolerance} of the target, or within {@code crowded} of it while something is close
     * ahead. {@return whether reached; false when an urgent task interrupted}
     */
    protected final boolean goTo(double tx, double tz, double ahead, double tolerance, double crowded) {
        if (!align(io.bearingTo(tx, tz))) {
            return false;
        }
        robot.setSpeeds(travelSpeed(), travelSpeed());
        long legEnds = 0;
        while (true) {
            step();
            if (urgent()) {
                return false;
            }
            Vec2 front = new Vec2(io.x(), io.z()).plus(Vec2.ofBearing(io.bearing()).times(ahead));
            double d = front.distanceTo(new Vec2(tx, tz));
            if (d <= tolerance || d <= crowded && !safe()) {
                robot.setSpeeds(0, 0);
                return true;
            }
            if (progressLost()) {
                escape();
                robot.setSpeeds(travelSpeed(), travelSpeed());
                legEnds = now() + Math.round(LEG * 1000);
            } else if (obstacleAhead()) {
                double delta = io.frontLeft.getValue() - io.frontRight.getValue();
                if (!avoidSideways(delta)) {
                    return false;
                }
                robot.setSpeeds(travelSpeed(), travelSpeed());
                legEnds = now() + Math.round(LEG * 1000);
            } else if (now() >= legEnds && Math.abs(KheperaIo.gap(io.bearingTo(tx, tz), io.bearing())) > DRIFT) {
                if (!align(io.bearingTo(tx, tz))) {
                    return false;
                }
                robot.setSpeeds(travelSpeed(), travelSpeed());
            }
        }
    }

    /** {@return the wheel speed of a drive to a point: the C programs' half speed, or the agents' travel speed} */
    private double travelSpeed() {
        return equal != null ? EqualCapabilities.TRAVEL : maxSpeed / 2;
    }

    /** {@return whether a drive to a point has stopped getting anywhere (never, for the thesis' programs)} */
    private boolean progressLost() {
        return equal != null && equal.progressLost();
    }

    /** A knocked-out cylinder: the delivery is over (then stop, or look around for it). */
    @Override
    protected void fallen() {
        delivering = false;
        super.fallen();
    }

    /** Spins away from an obstacle on the way (right when central: turning around would undo the way). */
    private boolean avoidSideways(double delta) {
        print(String.format(Locale.ROOT, "obstacle on the way: %.0f", delta));
        spinAway(delta >= -DELTA && delta <= DELTA ? 1 : delta);
        long since = now();
        while (!safe() && !clearTimedOut(since)) {
            step();
            if (urgent()) {
                return false;
            }
        }
        return true;
    }

    /**
     * Turns on the spot until the compass is within ±0.6 degrees of {@code desired} (C
     * {@code balance}/{@code balanceFunction}, Jason {@code !balance}): right while the gap is
     * positive, left otherwise. {@return false when an urgent task interrupted}
     */
    protected final boolean align(double desired) {
        while (true) {
            double gap = KheperaIo.gap(desired, io.bearing());
            if (Math.abs(gap) < ALIGNED) {
                robot.setSpeeds(0, 0);
                return true;
            }
            if (gap > 0) {
                robot.setSpeeds(TURN_FAST, TURN_SLOW);
            } else {
                robot.setSpeeds(TURN_SLOW, TURN_FAST);
            }
            step();
            if (urgent()) {
                return false;
            }
        }
    }
}
