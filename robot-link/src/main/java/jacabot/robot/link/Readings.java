package jacabot.robot.link;

import java.util.Arrays;

/** Formats readings for event logs: {@code KIND=value}, exact doubles, one token per reading. */
public final class Readings {
    private Readings() {
    }

    /** {@return e.g. {@code CENTRAL_DISTANCE=412.5}, {@code GPS=(0.1,0.0,-0.2)}, {@code #77=...} for an unknown id} */
    public static String format(SensorInfo info) {
        var kind = info.kind();
        String name = kind.map(Enum::name).orElse("#" + info.getId());
        SensorKind.Shape shape = kind.map(SensorKind::shape).orElse(SensorKind.Shape.SCALAR);
        switch (shape) {
            case COORD: {
                double[] c = info.getCoord();
                return name + "=(" + c[0] + "," + c[1] + "," + c[2] + ")";
            }
            case INTS:
                return name + "=" + Arrays.toString(info.getIntValues()).replace(" ", "");
            case DOUBLES:
                return name + "=" + Arrays.toString(info.getDoubleValues()).replace(" ", "");
            default:
                return name + "=" + info.getVal();
        }
    }
}
