package jacabot.robot.link;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Checks a reading's shape against the devices the controller declared in its {@link Protocol.Hello},
 * before any artifact sees it: the codec ({@link SensorInfoCodec}) only bounds what it allocates; an
 * empty gripper array or a NaN distance is legal Java and still poison for
 * code that indexes and compares. A reading is refused when its id was not declared, when it uses
 * fields its kind does not have, when an array has the wrong length for its kind, or when a value
 * is not finite.
 */
public final class ReadingCheck {
    /** RGB of the left, centre and right thirds. */
    public static final int CAMERA_SECTIONS_LENGTH = 9;
    /** {arm, grip} and {left, right}. */
    public static final int PAIR_LENGTH = 2;

    private final Set<Integer> declared;

    public ReadingCheck(List<Integer> declaredIds) {
        this.declared = new HashSet<>(declaredIds);
    }

    /** {@return why a batch is dropped (a negative step or time, or its first bad reading), or null} */
    public String problem(Uplink.Batch b) {
        if (b.step() < 0 || b.simTimeMs() < 0) {
            return "batch " + b.step() + " at t=" + b.simTimeMs() + " ms: negative step or time";
        }
        for (SensorInfo info : b.readings()) {
            String p = problem(info);
            if (p != null) {
                return "batch of step " + b.step() + " dropped: " + p;
            }
        }
        return null;
    }

    /** {@return why the reading is refused, or null when it is well-formed} */
    public String problem(SensorInfo info) {
        if (!declared.contains(info.getId())) {
            return "sensor id " + info.getId() + " was not declared by the robot";
        }
        var kind = SensorKind.of(info.getId());
        if (kind.isEmpty()) {
            return "sensor id " + info.getId() + " is unknown to this version";
        }
        SensorKind k = kind.get();
        int ints = info.intCount(), doubles = info.doubleCount();
        double[] c = info.getCoord();
        switch (k.shape()) {
            case SCALAR:
                if (ints != 0 || doubles != 0 || c[0] != 0 || c[1] != 0 || c[2] != 0) {
                    return k + ": a scalar reading carries arrays or coordinates";
                }
                return Double.isFinite(info.getVal()) ? null : k + ": value " + info.getVal() + " is not finite";
            case COORD:
                if (ints != 0 || doubles != 0 || info.getVal() != 0) {
                    return k + ": a coordinate reading carries other fields";
                }
                return Double.isFinite(c[0]) && Double.isFinite(c[1]) && Double.isFinite(c[2]) ? null
                        : k + ": a coordinate is not finite";
            case INTS:
                if (doubles != 0 || info.getVal() != 0) {
                    return k + ": an int-array reading carries other fields";
                }
                return intsProblem(k, info.ints()); // read, not kept: no copy
            case DOUBLES:
                if (ints != 0 || info.getVal() != 0) {
                    return k + ": a double-array reading carries other fields";
                }
                if (doubles != PAIR_LENGTH) {
                    return k + ": " + doubles + " values, expected " + PAIR_LENGTH;
                }
                for (double d : info.getDoubleValues()) {
                    if (!Double.isFinite(d)) {
                        return k + ": value " + d + " is not finite";
                    }
                }
                return null;
            default:
                return k + ": unknown shape";
        }
    }

    private static String intsProblem(SensorKind k, int[] v) {
        if (k == SensorKind.CAMERA_SECTIONS) {
            if (v.length != CAMERA_SECTIONS_LENGTH) {
                return k + ": " + v.length + " values, expected " + CAMERA_SECTIONS_LENGTH;
            }
            for (int x : v) {
                if (x < 0 || x > 255) {
                    return k + ": colour level " + x + " outside 0..255";
                }
            }
            return null;
        }
        if (k == SensorKind.CAMERA_IMAGE) {
            if (v.length < 2 || v[0] <= 0 || v[1] <= 0 || (long) v[0] * v[1] != v.length - 2L) {
                return k + ": " + v.length + " values do not make a width x height image";
            }
            return null;
        }
        return k + ": no int-array rule for this kind";
    }
}
