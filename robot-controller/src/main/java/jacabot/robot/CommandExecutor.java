package jacabot.robot;

import jacabot.robot.link.Command;
import jacabot.robot.link.CommandCode;
import jacabot.robot.link.ReceivedCommand;
import jacabot.robot.link.SensorKind;
import jacabot.sim.device.Gripper;
import jacabot.sim.robot.Robot;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Turns commands into actuator calls, in arrival order, on the simulation thread. Simple commands
 * take effect at once; manoeuvres ({@link Manoeuvre}) run over several steps and the commands that
 * arrive meanwhile wait for them, except {@code STOP}, which cancels everything before it: a stop
 * must never queue behind a turn.
 */
final class CommandExecutor {
    /** The thesis' C controller's speeds: forward (50, 50), turn left (20, 50), turn right (50, 20). */
    static final double CRUISE = 50, SLOW = 20;
    /** {@code backward} lasts four control steps, as {@code wb_robot_step(TIME_STEP*4)} in the thesis. */
    static final int BACKWARD_STEPS = 4;
    private static final long ARM_CAP_MS = 3000, GRIP_CAP_MS = 2000;

    private final Robot robot;
    private final DeviceSampler sampler;
    private final int controlStepMs;
    private final Consumer<String> log;
    private final Deque<ReceivedCommand> pending = new ArrayDeque<>();
    private Manoeuvre manoeuvre;

    CommandExecutor(Robot robot, DeviceSampler sampler, int controlStepMs, Consumer<String> log) {
        this.robot = robot;
        this.sampler = sampler;
        this.controlStepMs = controlStepMs;
        this.log = log;
    }

    /** Queues a received command; a {@code STOP} drops the manoeuvre and every command before it. */
    void submit(ReceivedCommand rc) {
        if (rc.command().code() == CommandCode.STOP) {
            pending.clear();
            manoeuvre = null;
        }
        pending.add(rc);
    }

    /**
     * Advances the running manoeuvre and applies waiting commands until one starts a manoeuvre.
     *
     * @return the commands that took effect (or started) now, in order
     */
    List<ReceivedCommand> tick(long nowMs) {
        List<ReceivedCommand> applied = new ArrayList<>();
        while (true) {
            if (manoeuvre != null) {
                if (!manoeuvre.tick(nowMs)) {
                    return applied;
                }
                manoeuvre = null;
            }
            ReceivedCommand next = pending.poll();
            if (next == null) {
                return applied;
            }
            if (apply(next.command())) {
                applied.add(next);
            }
        }
    }

    /** The fail-safe: cancels everything and stops the wheels. */
    void emergencyStop() {
        pending.clear();
        manoeuvre = null;
        robot.setSpeeds(0, 0);
    }

    /** {@return whether the wheels are turning} */
    boolean moving() {
        return robot.getWheels().getLeftSpeed() != 0 || robot.getWheels().getRightSpeed() != 0;
    }

    private boolean apply(Command c) {
        if (!c.code().isRobotCommand()) {
            return false; // link codes (heartbeat, step ack) never reach the actuators
        }
        double max = robot.getWheels().getMaxSpeed();
        switch (c.code()) {
            case STOP: robot.setSpeeds(0, 0); return true;
            case SET_SPEEDS: robot.setSpeeds(c.arg(0), c.arg(1)); return true;
            case FORWARD: robot.setSpeeds(CRUISE, CRUISE); return true;
            case TURN_LEFT: robot.setSpeeds(SLOW, CRUISE); return true;
            case TURN_RIGHT: robot.setSpeeds(CRUISE, SLOW); return true;
            case BACKWARD:
                manoeuvre = new Manoeuvre("backward")
                        .thenFor(() -> robot.setSpeeds(-max / 2, -max / 2), (long) BACKWARD_STEPS * controlStepMs)
                        .thenFor(() -> robot.setSpeeds(0, 0), 0);
                return true;
            case TURN_AROUND:
                manoeuvre = new Manoeuvre("turnAround")
                        .thenFor(() -> robot.setSpeeds(max / 2, -max / 2), turnAroundMs(max))
                        .thenFor(() -> robot.setSpeeds(0, 0), 0);
                return true;
            default:
                return applyGripperOrSensor(c);
        }
    }

    /** Spinning at ±max/2 turns at (max × unit / axle) rad/s: the time for 180°, in whole control steps. */
    private long turnAroundMs(double max) {
        double radPerSecond = max * robot.getWheels().getSpeedUnit() / robot.getWheels().getAxleLength();
        long ms = Math.round(Math.PI / radPerSecond * 1000);
        return (ms + controlStepMs - 1) / controlStepMs * controlStepMs;
    }

    private boolean applyGripperOrSensor(Command c) {
        switch (c.code()) {
            case ENABLE_SENSOR:
            case DISABLE_SENSOR:
                return applySensor(c);
            default:
                break;
        }
        if (!robot.hasGripper()) {
            log.accept("robot '" + robot.name() + "' has no gripper: " + c + " ignored");
            return false;
        }
        Gripper g = robot.getGripper();
        switch (c.code()) {
            case ARM_UP: g.armUp(); return true;
            case ARM_DOWN: g.armDown(); return true;
            case OPEN_GRIP: g.openGrip(); return true;
            case CLOSE_GRIP:
                if (c.arg(0) < 0 || c.arg(0) > 1) {
                    log.accept(c + " ignored: the target must be a finger position in 0..1");
                    return false;
                }
                g.closeGrip(); // the simulated fingers close until they meet the object
                return true;
            case CATCH:
                manoeuvre = new Manoeuvre("catching")
                        .then(() -> { g.openGrip(); g.armDown(); }, () -> g.isArmDown() && g.getGripPosition() == 0, ARM_CAP_MS)
                        .then(g::closeGrip, () -> g.getGripPosition() == 1, GRIP_CAP_MS);
                return true;
            case PUT_DOWN:
                manoeuvre = new Manoeuvre("putDown")
                        .then(g::armDown, g::isArmDown, ARM_CAP_MS)
                        .then(g::openGrip, () -> g.getGripPosition() == 0, GRIP_CAP_MS)
                        .then(g::armUp, g::isArmUp, ARM_CAP_MS);
                return true;
            default:
                log.accept(c + " is not a robot command: ignored");
                return false;
        }
    }

    private boolean applySensor(Command c) {
        int id = (int) c.arg(0);
        var kind = id == c.arg(0) ? SensorKind.of(id) : Optional.<SensorKind>empty();
        if (kind.isEmpty()) {
            log.accept(c + " ignored: no sensor kind has id " + c.arg(0));
            return false;
        }
        boolean done;
        if (c.code() == CommandCode.ENABLE_SENSOR) {
            double period = c.arg(1);
            if (period < 1 || period != Math.rint(period) || period > Integer.MAX_VALUE) {
                log.accept(c + " ignored: the sampling period must be a positive whole number of ms");
                return false;
            }
            done = sampler.enable(kind.get(), (int) period);
        } else {
            done = sampler.disable(kind.get());
        }
        if (!done) {
            log.accept(c + " ignored: robot '" + robot.name() + "' has no " + kind.get().description());
        }
        return done;
    }
}
