package jacabot.robot.link;

import java.io.ObjectInputFilter;

/**
 * The deserialization filter of the sensor data stream: only {@link SensorInfo} and its
 * {@code int[]}/{@code double[]} fields may be read, with limits on depth, array length, back
 * references and the bytes one object may take. Anything else is rejected before it is built, so a
 * hostile or confused peer cannot make the middleware instantiate a foreign class or allocate a huge
 * array; the reader then closes the connection with {@link #lastRejection()} as the reason.
 *
 * <p>One filter per stream: the byte limit is per object (the stream's own byte count grows for
 * the life of the connection), so {@link #beginObject()} marks where each top-level object starts.
 */
public final class SensorInfoFilter implements ObjectInputFilter {
    /**
     * Limits; {@link #DEFAULT} fits a 640×480 camera image.
     *
     * @param maxBytesPerFrame   bytes one batch may take in all (the per-object limit times the batch
     *                           length would allow gigabytes)
     * @param maxObjectsPerStream readings one object stream may carry before it restarts
     *                           ({@link Uplink#RESTART}): the reader's handle table keeps them all
     */
    public record Limits(int maxArrayLength, int maxDepth, long maxReferences, long maxBytesPerObject,
                         long maxBytesPerFrame, long maxObjectsPerStream) {
        public static final Limits DEFAULT = new Limits(640 * 480 + 2, 3, 100_000, 8L * (640 * 480 + 2) + 4096,
                4L * (640 * 480 + 2) + 64 * 1024, 16_384);

        public Limits(int maxArrayLength, int maxDepth, long maxReferences, long maxBytesPerObject) {
            this(maxArrayLength, maxDepth, maxReferences, maxBytesPerObject, maxBytesPerObject + 64 * 1024, 16_384);
        }
    }

    private final Limits limits;
    private long objectStart = -1;
    private long frameStart = -1;
    private long referencesStart;
    private String lastRejection;

    public SensorInfoFilter(Limits limits) {
        this.limits = limits;
    }

    /** Called before each top-level {@code readObject}: the byte limit counts from here. */
    public void beginObject() {
        objectStart = -1;
    }

    /** Called before each frame: the frame's byte limit counts from here. */
    public void beginFrame() {
        frameStart = -1;
    }

    /** {@return why the last object was rejected, or null} */
    public String lastRejection() {
        return lastRejection;
    }

    @Override
    public Status checkInput(FilterInfo info) {
        if (objectStart < 0) {
            objectStart = info.streamBytes();
            referencesStart = info.references();
        }
        if (frameStart < 0) {
            frameStart = objectStart;
        }
        Class<?> type = info.serialClass();
        if (type != null) {
            if (type.isArray()) {
                Class<?> component = type.getComponentType();
                if (component != int.class && component != double.class) {
                    return reject("array of " + component.getName() + " is not allowed");
                }
                if (info.arrayLength() > limits.maxArrayLength()) {
                    return reject("array of " + info.arrayLength() + " elements exceeds the limit of "
                            + limits.maxArrayLength());
                }
            } else if (type != SensorInfo.class) {
                return reject("class " + type.getName() + " is not allowed (only SensorInfo)");
            }
        }
        if (info.depth() > limits.maxDepth()) {
            return reject("nesting depth " + info.depth() + " exceeds " + limits.maxDepth());
        }
        // the JDK counts references over the whole stream (reset() does not clear the count), so
        // the limit applies to each object read
        long references = info.references() - referencesStart;
        if (references > limits.maxReferences()) {
            return reject(references + " back references exceed " + limits.maxReferences());
        }
        if (info.streamBytes() - objectStart > limits.maxBytesPerObject()) {
            return reject("object larger than " + limits.maxBytesPerObject() + " bytes");
        }
        if (info.streamBytes() - frameStart > limits.maxBytesPerFrame()) {
            return reject("batch larger than " + limits.maxBytesPerFrame() + " bytes");
        }
        return Status.ALLOWED;
    }

    private Status reject(String reason) {
        lastRejection = reason;
        return Status.REJECTED;
    }
}
