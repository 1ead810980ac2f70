package jacabot.robot.link;

import java.io.ObjectInputFilter;

/**
 * The limits of the sensor data stream, and its deserialization filter. Since protocol version 3
 * the stream carries no objects ({@link SensorInfoCodec}): the filter stays installed on the
 * middleware's {@code ObjectInputStream} as a second lock and refuses every class, so even a reader
 * changed to call {@code readObject} would build nothing from the peer's bytes. The limits bound
 * what the codec allocates: an array's length, a reading's bytes, a batch's bytes, and the readings
 * between two stream restarts.
 */
public final class SensorInfoFilter implements ObjectInputFilter {
    /**
     * Limits; {@link #DEFAULT} fits a 640×480 camera image.
     *
     * @param maxArrayLength    the longest array a reading may carry
     * @param maxDepth          version 2's bound on object nesting; unused since version 3 carries no objects
     * @param maxReferences     version 2's bound on back references; unused likewise
     * @param maxBytesPerObject bytes one reading may take
     * @param maxBytesPerFrame   bytes the readings of one batch may take in all (the per-reading limit
     *                           times the batch length would allow gigabytes)
     * @param maxObjectsPerStream readings one object stream may carry before it restarts
     *                           ({@link Uplink#RESTART})
     */
    public record Limits(int maxArrayLength, int maxDepth, long maxReferences, long maxBytesPerObject,
                         long maxBytesPerFrame, long maxObjectsPerStream) {
        public static final Limits DEFAULT = new Limits(640 * 480 + 2, 3, 100_000, 8L * (640 * 480 + 2) + 4096,
                4L * (640 * 480 + 2) + 64 * 1024, 16_384);

        public Limits(int maxArrayLength, int maxDepth, long maxReferences, long maxBytesPerObject) {
            this(maxArrayLength, maxDepth, maxReferences, maxBytesPerObject, maxBytesPerObject + 64 * 1024, 16_384);
        }
    }

    private String lastRejection;

    /** {@return why the last object was rejected, or null} */
    public String lastRejection() {
        return lastRejection;
    }

    @Override
    public Status checkInput(FilterInfo info) {
        Class<?> type = info.serialClass();
        return reject(type == null ? "no object is allowed on the sensor data stream"
                : "class " + type.getName() + " is not allowed (the sensor data stream carries no objects)");
    }

    private Status reject(String reason) {
        lastRejection = reason;
        return Status.REJECTED;
    }
}
