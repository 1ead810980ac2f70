package jacabot.robot.link;

import java.util.Optional;

/**
 * The integer codes of the commands the middleware sends to the robot controller (thesis §2.4:
 * "the artifact simply sends an integer number ... both sides have to agree on the meaning of each
 * integer value"). Defined once here and shared by both sides; the handshake checks
 * {@link Protocol#VERSION} so that two builds that disagree never talk. Codes are part of the
 * protocol: never renumber, only add (and bump the version).
 *
 * <p>The motion codes keep the thesis' names as the artifact's operations ({@link #operation()}).
 * {@code BACKWARD}, {@code TURN_AROUND}, {@code CATCH} and {@code PUT_DOWN} are manoeuvres that the
 * controller carries out over several control steps, as the functional layer "transforms commands
 * into simple mechanical actions"; commands that arrive meanwhile wait for them, except {@code STOP}.
 */
public enum CommandCode {
    /** Both wheels stopped; also cancels a manoeuvre in progress. */
    STOP(0, 0, "stop"),
    /** (left, right) wheel speeds in speed units, clamped to ±max by the robot. */
    SET_SPEEDS(1, 2, "setSpeeds"),
    /** Both wheels at 50 (the thesis' C controller's forward). */
    FORWARD(2, 0, "forward"),
    /** Manoeuvre: back at half the maximum speed for four control steps, then stop. */
    BACKWARD(3, 0, "backward"),
    /** Left 20, right 50. */
    TURN_LEFT(4, 0, "turnLeft"),
    /** Left 50, right 20. */
    TURN_RIGHT(5, 0, "turnRight"),
    /** Manoeuvre: spin on the spot at half speed for about 180 degrees, then stop. */
    TURN_AROUND(6, 0, "turnAround"),
    ARM_UP(7, 0, "arm_up"),
    ARM_DOWN(8, 0, "arm_down"),
    OPEN_GRIP(9, 0, "open_grip"),
    /** (target) finger position 0 open..1 closed; the simulated gripper closes until it meets the object. */
    CLOSE_GRIP(10, 1, "close_grip"),
    /** Manoeuvre: open the fingers, lower the arm, then close the fingers (the thesis' {@code catching}). */
    CATCH(11, 0, "catching"),
    /** Manoeuvre: lower the arm, open the fingers, raise the arm (the thesis' {@code putDown}). */
    PUT_DOWN(12, 0, "putDown"),
    /** (kind id, sampling period ms) enables a device; the controller enables every device at start. */
    ENABLE_SENSOR(20, 2, "enableSensor"),
    /** (kind id) disables a device. */
    DISABLE_SENSOR(21, 1, "disableSensor"),
    /** Link: "the agent platform is alive"; resets the controller's fail-safe timer. */
    HEARTBEAT(100, 0, "heartbeat"),
    /** Link, lockstep: (step) the commands of that step are all sent; the simulation may advance. */
    STEP_ACK(101, 1, "stepAck");

    private final int code;
    private final int arity;
    private final String operation;

    CommandCode(int code, int arity, String operation) {
        this.code = code;
        this.arity = arity;
        this.operation = operation;
    }

    /** {@return the integer sent on the wire} */
    public int code() {
        return code;
    }

    /** {@return how many double arguments follow the code} */
    public int arity() {
        return arity;
    }

    /** {@return the name of the middleware artifact's operation (the thesis' spelling)} */
    public String operation() {
        return operation;
    }

    /** {@return whether this code drives the robot (as opposed to the link's own codes)} */
    public boolean isRobotCommand() {
        return code < HEARTBEAT.code;
    }

    /** {@return the code of a wire integer, empty when this version does not know it} */
    public static Optional<CommandCode> of(int code) {
        for (CommandCode c : values()) {
            if (c.code == code) {
                return Optional.of(c);
            }
        }
        return Optional.empty();
    }
}
