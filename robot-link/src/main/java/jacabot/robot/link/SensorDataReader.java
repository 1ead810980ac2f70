package jacabot.robot.link;

import java.io.BufferedInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.ObjectInputStream;
import java.io.ObjectStreamException;
import java.io.UTFDataFormatException;
import java.util.ArrayList;
import java.util.List;

/**
 * The middleware's end of the sensor data stream: reads {@link Uplink} frames through an
 * {@code ObjectInputStream}, readings in {@link SensorInfoCodec}'s encoding. Nothing is deserialized:
 * the stream's {@link SensorInfoFilter} stays installed and refuses every class, so an object put
 * where a reading belongs is never built. Every way the stream can be wrong (an object, a huge
 * array, an unknown tag, a truncated frame, garbage) becomes one {@link ProtocolException} with a
 * readable reason; the caller closes the connection.
 */
public final class SensorDataReader {
    private final BufferedInputStream buffered;
    private ObjectInputStream in;
    private final SensorInfoFilter filter;
    private final SensorInfoFilter.Limits limits;
    private long objectsInStream;
    private volatile long frameStartNanos;
    private LinkCosts costs;
    private LockstepSpin spin;
    /** Bytes of the next frame at hand: the object stream may hold some already, past the buffer's. */
    private final LockstepSpin.Ready frameReady;
    /** The int arrays' bytes, kept from frame to frame (frames are read on one thread). */
    private final SensorInfoCodec.Scratch scratch = new SensorInfoCodec.Scratch();

    /**
     * Reads the stream header (so it blocks until the controller has written it).
     *
     * @throws ProtocolException when the bytes are not an object stream
     */
    public SensorDataReader(InputStream in, SensorInfoFilter.Limits limits) throws IOException {
        this.filter = new SensorInfoFilter();
        this.limits = limits;
        this.buffered = new BufferedInputStream(in);
        this.frameReady = () -> this.in.available() > 0 || buffered.available() > 0;
        openStream();
    }

    private void openStream() throws IOException {
        try {
            this.in = new ObjectInputStream(buffered);
        } catch (EOFException e) {
            throw new ProtocolException("the controller closed the connection before its sensor data stream began");
        } catch (ObjectStreamException e) {
            throw new ProtocolException("garbage instead of a sensor data stream: " + e.getMessage());
        }
        this.in.setObjectInputFilter(filter);
        objectsInStream = 0;
    }

    /**
     * {@return {@code System.nanoTime()} when the frame being read began (its tag arrived), 0 between
     * frames}: a watchdog closes a connection that takes too long to finish a frame (a client sending
     * a byte every few seconds would otherwise hold the reading thread for ever)
     */
    public long frameStartNanos() {
        return frameStartNanos;
    }

    /** From now on, adds the time spent decoding frames (from their first byte on) to {@code costs}. */
    public void measure(LinkCosts costs) {
        this.costs = costs;
    }

    /** From now on, spins before each blocking read while that pays: for a lockstep link ({@link LockstepSpin}). */
    public void spinWith(LockstepSpin spin) {
        this.spin = spin;
    }

    /**
     * Reads the next frame, blocking.
     *
     * @return the frame, or null when the controller closed the connection between two frames
     */
    public Uplink read() throws IOException {
        while (true) {
            frameStartNanos = 0;
            int tag;
            try {
                if (spin != null) {
                    spin.await(frameReady);
                }
                tag = in.read();
            } catch (ObjectStreamException e) {
                throw garbage(e);
            }
            if (tag < 0) {
                return null;
            }
            frameStartNanos = Math.max(1, System.nanoTime());
            if (tag == Uplink.RESTART) {
                openStream(); // a new header follows: the old stream's handles go
                continue;
            }
            try {
                if (costs == null) {
                    return readFrame(tag);
                }
                long t0 = System.nanoTime();
                Uplink frame = readFrame(tag);
                costs.addDecoding(System.nanoTime() - t0);
                return frame;
            } finally {
                frameStartNanos = 0;
            }
        }
    }

    private Uplink readFrame(int tag) throws IOException {
        try {
            switch (tag) {
                case Uplink.BATCH: return readBatch();
                case Uplink.STEP_MARKER: return new Uplink.StepMarker(in.readLong(), in.readLong(), in.readBoolean());
                case Uplink.APPLIED:
                    return new Uplink.Applied(in.readInt(), in.readInt(), in.readLong(), in.readLong(), in.readLong(),
                            in.readLong());
                case Uplink.FAIL_SAFE: return new Uplink.FailSafe(in.readLong(), in.readUTF());
                case Uplink.BYE: return new Uplink.Bye(in.readUTF());
                default: throw new ProtocolException("garbage on the sensor data stream: unknown frame tag " + tag);
            }
        } catch (EOFException e) {
            // in block data, an object where a reading's fields belong also ends the primitives
            throw new ProtocolException("truncated frame: the sensor data stream ended inside a frame, or carried "
                    + "something other than its fields (tag " + tag + ")");
        } catch (ObjectStreamException | UTFDataFormatException e) {
            throw garbage(e);
        }
    }

    private Uplink.Batch readBatch() throws IOException {
        long step = in.readLong(), simTime = in.readLong(), sampled = in.readLong();
        int count = in.readInt();
        if (count < 0 || count > Protocol.MAX_READINGS_PER_BATCH) {
            throw new ProtocolException("garbage on the sensor data stream: a batch of " + count + " readings");
        }
        List<SensorInfo> readings = new ArrayList<>(count);
        long budget = limits.maxBytesPerFrame();
        for (int i = 0; i < count; i++) {
            if (++objectsInStream > limits.maxObjectsPerStream()) {
                throw new ProtocolException("garbage on the sensor data stream: more than " + limits.maxObjectsPerStream()
                        + " readings without a stream restart");
            }
            SensorInfoCodec.Decoded d = SensorInfoCodec.read(in, limits, budget, scratch);
            budget -= d.bytes();
            readings.add(d.info());
        }
        return new Uplink.Batch(step, simTime, sampled, readings);
    }

    private static ProtocolException garbage(IOException e) {
        return new ProtocolException("garbage on the sensor data stream: " + e, e);
    }
}
