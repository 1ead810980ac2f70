package jacabot.robot.link;

import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectInputStream;
import java.io.Serializable;
import java.util.Arrays;
import java.util.Optional;
import java.util.function.Function;

/**
 * One sensor reading as it travels from the robot controller to the middleware artifact
 * (thesis Appendix A): the kind of reading and its value, which is a single double, a coordinate
 * triple, an int array (image sections or RGB) or a double array.
 *
 * <p>Unlike the thesis' class, the double-array constructor keeps the id, and the value fields are
 * primitive. It stays {@code Serializable}, as in the thesis, but the link writes it with
 * {@link SensorInfoCodec} (protocol version 3).
 */
public final class SensorInfo implements Serializable {
    private static final long serialVersionUID = 1L;
    private static final int[] NO_INTS = {};
    private static final double[] NO_DOUBLES = {};

    private final int id;
    private final double value;
    private final int[] intValues;
    private final double x;
    private final double y;
    private final double z;
    private final double[] doubleValues;

    private SensorInfo(int id, double value, int[] ints, double x, double y, double z, double[] doubles) {
        this.id = id;
        this.value = value;
        this.intValues = ints;
        this.x = x;
        this.y = y;
        this.z = z;
        this.doubleValues = doubles;
    }

    /** A scalar reading, e.g. a distance sensor or the battery level. */
    public SensorInfo(int id, double value) {
        this(id, value, NO_INTS, 0, 0, 0, NO_DOUBLES);
    }

    /** An int-array reading, e.g. the RGB levels of the camera's image sections. */
    public SensorInfo(int id, int[] values) {
        this(id, 0, values.clone(), 0, 0, 0, NO_DOUBLES);
    }

    /** A coordinate triple, e.g. a GPS position. */
    public SensorInfo(int id, double x, double y, double z) {
        this(id, 0, NO_INTS, x, y, z, NO_DOUBLES);
    }

    /** A double-array reading. */
    public SensorInfo(int id, double[] values) {
        this(id, 0, NO_INTS, 0, 0, 0, values.clone());
    }

    /**
     * An int-array reading that takes {@code values} as its own, without the copy the constructor
     * makes: for a sampler that fills a new array for each reading (a camera image, every control
     * step) and never touches it again.
     */
    public static SensorInfo owning(int id, int[] values) {
        return new SensorInfo(id, 0, values, 0, 0, 0, NO_DOUBLES);
    }

    /** A reading as the compact codec read it (null arrays: empty); the arrays are not copied. */
    static SensorInfo decoded(int id, double value, int[] ints, double x, double y, double z, double[] doubles) {
        return new SensorInfo(id, value, ints == null ? NO_INTS : ints, x, y, z, doubles == null ? NO_DOUBLES : doubles);
    }

    // the fields as they are, for the codec (no copies)
    double value() {
        return value;
    }

    double x() {
        return x;
    }

    double y() {
        return y;
    }

    double z() {
        return z;
    }

    int[] ints() {
        return intValues;
    }

    double[] doubles() {
        return doubleValues;
    }

    public int getId() {
        return id;
    }

    /** {@return the registered kind of this reading's id, empty for an id this version does not know} */
    public Optional<SensorKind> kind() {
        return SensorKind.of(id);
    }

    public double getVal() {
        return value;
    }

    public double[] getCoord() {
        return new double[] {x, y, z};
    }

    public int[] getIntValues() {
        return intValues.clone();
    }

    public double[] getDoubleValues() {
        return doubleValues.clone();
    }

    /**
     * {@return what {@code reader} makes of the int array, lent to it without a copy}: for a reader that
     * only reads the array during the call and keeps nothing of it (the far sight scanning the camera
     * image: the copy {@link #getIntValues} makes was about a seventh of the middleware thread's
     * allocation in experiment 4). A reader that wrote to the array would change the reading.
     */
    public <R> R readInts(Function<int[], R> reader) {
        return reader.apply(intValues);
    }

    /** {@return the length of the int array, without copying it} */
    public int intCount() {
        return intValues.length;
    }

    /** {@return the length of the double array, without copying it} */
    public int doubleCount() {
        return doubleValues.length;
    }

    /** A stream may carry any field values: refuse the ones the constructors never make. */
    private void readObject(ObjectInputStream in) throws IOException, ClassNotFoundException {
        in.defaultReadObject();
        if (intValues == null || doubleValues == null) {
            throw new InvalidObjectException("SensorInfo with a null array");
        }
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof SensorInfo)) {
            return false;
        }
        SensorInfo s = (SensorInfo) o;
        return id == s.id && Double.compare(value, s.value) == 0 && Arrays.equals(intValues, s.intValues)
                && Double.compare(x, s.x) == 0 && Double.compare(y, s.y) == 0 && Double.compare(z, s.z) == 0
                && Arrays.equals(doubleValues, s.doubleValues);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * Integer.hashCode(id) + Double.hashCode(value)) + Arrays.hashCode(intValues);
    }

    @Override
    public String toString() {
        return "SensorInfo[id=" + id + ", value=" + value + ", ints=" + Arrays.toString(intValues)
                + ", xyz=(" + x + "," + y + "," + z + "), doubles=" + Arrays.toString(doubleValues) + "]";
    }
}
