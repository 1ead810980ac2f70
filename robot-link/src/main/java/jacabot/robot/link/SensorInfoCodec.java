package jacabot.robot.link;

import java.io.DataInput;
import java.io.DataOutput;
import java.io.IOException;
import java.nio.ByteBuffer;

/**
 * The compact encoding of one {@link SensorInfo} on the sensor data stream (protocol version 3):
 * {@code int id, byte fields}, then only the fields the flags name, in this order: {@code double
 * value} ({@link #VALUE}), {@code double x, y, z} ({@link #COORDINATES}), {@code int n, int × n}
 * ({@link #INTS}), {@code int n, double × n} ({@link #DOUBLES}). A field left out is zero or empty,
 * so every reading, well-formed or not, reads back equal to what was written ({@link ReadingCheck}
 * judges it after).
 *
 * <p>Why not {@code writeObject} as the thesis does: Java serialization costs a reflective object,
 * two arrays and the filter's callbacks per reading, which was the largest single item of the
 * middleware's reading thread in a lockstep step ({@code docs/performance.md}). Nothing on the
 * stream is deserialized any more, so no class but the primitive arrays sized here is ever built
 * from the peer's bytes.
 */
public final class SensorInfoCodec {
    static final int VALUE = 1, COORDINATES = 2, INTS = 4, DOUBLES = 8;
    private static final int ALL = VALUE | COORDINATES | INTS | DOUBLES;

    private SensorInfoCodec() {
    }

    /** Writes {@code info} (no flush). */
    public static void write(DataOutput out, SensorInfo info) throws IOException {
        write(out, info, new Scratch());
    }

    /** As {@link #write(DataOutput, SensorInfo)}, the int arrays' bytes put in {@code scratch}'s array, which one writer keeps. */
    static void write(DataOutput out, SensorInfo info, Scratch scratch) throws IOException {
        int flags = (Double.doubleToRawLongBits(info.value()) != 0 ? VALUE : 0)
                | (nonZero(info.x()) || nonZero(info.y()) || nonZero(info.z()) ? COORDINATES : 0)
                | (info.intCount() > 0 ? INTS : 0) | (info.doubleCount() > 0 ? DOUBLES : 0);
        out.writeInt(info.getId());
        out.writeByte(flags);
        if ((flags & VALUE) != 0) {
            out.writeDouble(info.value());
        }
        if ((flags & COORDINATES) != 0) {
            out.writeDouble(info.x());
            out.writeDouble(info.y());
            out.writeDouble(info.z());
        }
        if ((flags & INTS) != 0) {
            int[] v = info.ints();
            out.writeInt(v.length);
            // the bytes writeInt would write one int at a time (big-endian), in one call: the
            // camera image is 514 ints a control step
            byte[] bytes = scratch.atLeast(4 * v.length);
            ByteBuffer.wrap(bytes, 0, 4 * v.length).asIntBuffer().put(v);
            out.write(bytes, 0, 4 * v.length);
        }
        if ((flags & DOUBLES) != 0) {
            double[] v = info.doubles();
            out.writeInt(v.length);
            for (double d : v) {
                out.writeDouble(d);
            }
        }
    }

    private static boolean nonZero(double d) {
        return Double.doubleToRawLongBits(d) != 0;
    }

    /**
     * Reads one reading, refusing an array longer than {@code limits} allow, or a reading that
     * would take more than its byte budget, before allocating it.
     *
     * @param budget the bytes the reading may take at most (what is left of its batch's)
     * @return the reading and, through {@link Decoded#bytes()}, the bytes it took
     * @throws ProtocolException for unknown flags or a limit passed
     */
    static Decoded read(DataInput in, SensorInfoFilter.Limits limits, long budget) throws IOException {
        return read(in, limits, budget, new Scratch());
    }

    /**
     * As {@link #read(DataInput, SensorInfoFilter.Limits, long)}, the int arrays' bytes read into
     * {@code scratch}'s array, which one reader keeps from reading to reading: a camera image each control
     * step took a new byte array as large as its int array (about a tenth of the middleware thread's
     * allocation in experiment 4).
     */
    static Decoded read(DataInput in, SensorInfoFilter.Limits limits, long budget, Scratch scratch) throws IOException {
        int id = in.readInt();
        int flags = in.readUnsignedByte();
        if ((flags & ~ALL) != 0) {
            throw new ProtocolException("garbage on the sensor data stream: reading " + id + " has field flags " + flags);
        }
        long bytes = 5;
        double value = (flags & VALUE) != 0 ? in.readDouble() : 0;
        bytes += (flags & VALUE) != 0 ? 8 : 0;
        double x = 0, y = 0, z = 0;
        if ((flags & COORDINATES) != 0) {
            x = in.readDouble();
            y = in.readDouble();
            z = in.readDouble();
            bytes += 24;
        }
        int[] ints = null;
        if ((flags & INTS) != 0) {
            int n = length(in, limits);
            bytes += 4 + 4L * n;
            within(bytes, limits, budget);
            ints = new int[n];
            byte[] raw = scratch.atLeast(4 * n);
            in.readFully(raw, 0, 4 * n); // as n readInt calls, in one
            ByteBuffer.wrap(raw, 0, 4 * n).asIntBuffer().get(ints);
        }
        double[] doubles = null;
        if ((flags & DOUBLES) != 0) {
            int n = length(in, limits);
            bytes += 4 + 8L * n;
            within(bytes, limits, budget);
            doubles = new double[n];
            for (int i = 0; i < n; i++) {
                doubles[i] = in.readDouble();
            }
        }
        return new Decoded(SensorInfo.decoded(id, value, ints, x, y, z, doubles), bytes);
    }

    /** Bytes kept for the int arrays by one reader or writer (one thread at a time), grown as needed. */
    static final class Scratch {
        private byte[] bytes = new byte[0];

        byte[] atLeast(int n) {
            if (bytes.length < n) {
                bytes = new byte[n];
            }
            return bytes;
        }
    }

    /** A reading read, and the bytes it took on the stream. */
    record Decoded(SensorInfo info, long bytes) {
    }

    private static int length(DataInput in, SensorInfoFilter.Limits limits) throws IOException {
        int n = in.readInt();
        if (n < 0 || n > limits.maxArrayLength()) {
            throw new ProtocolException("rejected: array of " + n + " elements exceeds the limit of " + limits.maxArrayLength());
        }
        return n;
    }

    private static void within(long bytes, SensorInfoFilter.Limits limits, long budget) throws ProtocolException {
        if (bytes > limits.maxBytesPerObject()) {
            throw new ProtocolException("rejected: reading larger than " + limits.maxBytesPerObject() + " bytes");
        }
        if (bytes > budget) {
            throw new ProtocolException("rejected: batch larger than " + limits.maxBytesPerFrame() + " bytes");
        }
    }
}
