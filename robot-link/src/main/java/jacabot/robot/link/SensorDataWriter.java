package jacabot.robot.link;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.util.List;

/**
 * The controller's end of the sensor data stream: an {@code ObjectOutputStream}, as in the thesis,
 * carrying the {@link Uplink} frames (primitive headers, then each {@link SensorInfo} in the compact
 * encoding of {@link SensorInfoCodec}; version 2 wrote them as serialized objects). Every
 * {@code resetEvery} batches the object stream restarts ({@link Uplink#RESTART}, then a new stream
 * header), as version 2 did to bound both ends' object handle tables; the reader still refuses a
 * stream that goes on too long without one.
 */
public final class SensorDataWriter {
    private final BufferedOutputStream buffered;
    private ObjectOutputStream out;
    private final int resetEvery;
    private int batchesSinceReset;
    private LinkCosts costs;
    /** Frames written, and of them flushed: an in-process reader reads only whole, flushed frames ({@link MemoryLink}). */
    private long framesWritten, framesFlushed;
    /** The int arrays' bytes, kept from step to step. */
    private final SensorInfoCodec.Scratch scratch = new SensorInfoCodec.Scratch();

    /** Writes the stream header at once. */
    public SensorDataWriter(OutputStream out, int resetEvery) throws IOException {
        if (resetEvery < 1) {
            throw new IllegalArgumentException("resetEvery must be >= 1, got " + resetEvery);
        }
        this.buffered = new BufferedOutputStream(out);
        this.out = new ObjectOutputStream(buffered);
        this.out.flush();
        this.resetEvery = resetEvery;
    }

    /** {@return the frames written and flushed so far (a step is two: its batch and its marker)} */
    public synchronized long framesFlushed() {
        return framesFlushed;
    }

    private void flushed() throws IOException {
        out.flush();
        framesFlushed = framesWritten;
    }

    /** From now on, adds the time spent encoding and writing steps to {@code costs}. */
    public synchronized void measure(LinkCosts costs) {
        this.costs = costs;
    }

    /** Writes a step's batch and its step marker, and flushes. */
    public synchronized void writeStep(Uplink.Batch batch, Uplink.StepMarker marker) throws IOException {
        long t0 = costs == null ? 0 : System.nanoTime();
        if (++batchesSinceReset >= resetEvery) {
            out.writeByte(Uplink.RESTART);
            out.flush();
            out = new ObjectOutputStream(buffered); // a new header: both ends forget every object so far
            batchesSinceReset = 0;
        }
        out.writeByte(Uplink.BATCH);
        out.writeLong(batch.step());
        out.writeLong(batch.simTimeMs());
        out.writeLong(batch.sampledMicros());
        List<SensorInfo> readings = batch.readings();
        out.writeInt(readings.size());
        for (SensorInfo info : readings) {
            SensorInfoCodec.write(out, info, scratch); // under the writer's lock
        }
        out.writeByte(Uplink.STEP_MARKER);
        out.writeLong(marker.step());
        out.writeLong(marker.simTimeMs());
        out.writeBoolean(marker.awaitsAck());
        framesWritten += 2;
        if (costs == null) {
            flushed();
            return;
        }
        long t1 = System.nanoTime();
        flushed();
        costs.addEncoding(t1 - t0);
        costs.addWriting(System.nanoTime() - t1);
    }

    public synchronized void writeApplied(Uplink.Applied a) throws IOException {
        writeApplied(a, true);
    }

    /** Writes an applied report; unflushed, it leaves with the next frame that flushes (lockstep's next step). */
    public synchronized void writeApplied(Uplink.Applied a, boolean flush) throws IOException {
        out.writeByte(Uplink.APPLIED);
        out.writeInt(a.seq());
        out.writeInt(a.code());
        out.writeLong(a.step());
        out.writeLong(a.simTimeMs());
        out.writeLong(a.receivedMicros());
        out.writeLong(a.appliedMicros());
        framesWritten++;
        if (flush) {
            flushed();
        }
    }

    public synchronized void writeFailSafe(Uplink.FailSafe f) throws IOException {
        out.writeByte(Uplink.FAIL_SAFE);
        out.writeLong(f.simTimeMs());
        out.writeUTF(f.reason());
        framesWritten++;
        flushed();
    }

    public synchronized void writeBye(Uplink.Bye bye) throws IOException {
        out.writeByte(Uplink.BYE);
        out.writeUTF(bye.reason());
        framesWritten++;
        flushed();
    }
}
