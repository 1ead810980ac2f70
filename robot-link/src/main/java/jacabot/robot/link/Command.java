package jacabot.robot.link;

import java.util.Arrays;
import java.util.Objects;

/**
 * One command from the middleware to the robot controller: a {@link CommandCode} and its
 * arguments, all finite doubles. Immutable; the factories name the thesis' operations.
 */
public final class Command {
    private final CommandCode code;
    private final double[] args;

    private Command(CommandCode code, double... args) {
        this.code = Objects.requireNonNull(code, "code");
        if (args.length != code.arity()) {
            throw new IllegalArgumentException(code + " takes " + code.arity() + " argument(s), got " + args.length);
        }
        for (double a : args) {
            if (!Double.isFinite(a)) {
                throw new IllegalArgumentException(code + " needs finite arguments, got " + Arrays.toString(args));
            }
        }
        this.args = args.clone();
    }

    /** {@return a command} @throws IllegalArgumentException for a wrong number of arguments or a non-finite one */
    public static Command of(CommandCode code, double... args) {
        return new Command(code, args);
    }

    public static Command stop() {
        return of(CommandCode.STOP);
    }

    public static Command setSpeeds(double left, double right) {
        return of(CommandCode.SET_SPEEDS, left, right);
    }

    public static Command forward() {
        return of(CommandCode.FORWARD);
    }

    public static Command backward() {
        return of(CommandCode.BACKWARD);
    }

    public static Command turnLeft() {
        return of(CommandCode.TURN_LEFT);
    }

    public static Command turnRight() {
        return of(CommandCode.TURN_RIGHT);
    }

    public static Command turnAround() {
        return of(CommandCode.TURN_AROUND);
    }

    public static Command armUp() {
        return of(CommandCode.ARM_UP);
    }

    public static Command armDown() {
        return of(CommandCode.ARM_DOWN);
    }

    public static Command openGrip() {
        return of(CommandCode.OPEN_GRIP);
    }

    /** @param target finger position aimed at, 0 open..1 closed */
    public static Command closeGrip(double target) {
        return of(CommandCode.CLOSE_GRIP, target);
    }

    public static Command catching() {
        return of(CommandCode.CATCH);
    }

    public static Command putDown() {
        return of(CommandCode.PUT_DOWN);
    }

    public static Command enableSensor(SensorKind kind, int samplingPeriodMs) {
        return of(CommandCode.ENABLE_SENSOR, kind.id(), samplingPeriodMs);
    }

    public static Command disableSensor(SensorKind kind) {
        return of(CommandCode.DISABLE_SENSOR, kind.id());
    }

    public static Command heartbeat() {
        return of(CommandCode.HEARTBEAT);
    }

    public static Command stepAck(long step) {
        return of(CommandCode.STEP_ACK, step);
    }

    public CommandCode code() {
        return code;
    }

    /** {@return argument i} */
    public double arg(int i) {
        return args[i];
    }

    /** {@return a copy of the arguments} */
    public double[] args() {
        return args.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Command && ((Command) o).code == code && Arrays.equals(((Command) o).args, args);
    }

    @Override
    public int hashCode() {
        return 31 * code.hashCode() + Arrays.hashCode(args);
    }

    /** {@return e.g. {@code setSpeeds(50.0,-10.0)}, the form the event logs use} */
    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder(code.operation());
        if (args.length > 0) {
            sb.append('(');
            for (int i = 0; i < args.length; i++) {
                sb.append(i > 0 ? "," : "").append(args[i]);
            }
            sb.append(')');
        }
        return sb.toString();
    }
}
