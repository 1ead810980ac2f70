package jacabot.robot.link;

import java.util.concurrent.atomic.LongAdder;

/**
 * Where the link's own time goes, in wall-clock nanoseconds, for the benchmarks: sampling the
 * devices into {@link SensorInfo}s, encoding a step's frame, writing to the socket (the controller's
 * frames, the middleware's lockstep answers), decoding frames (on the middleware's side), and the
 * controller's lockstep wait for the answer (the agent's work as the simulation thread sees it). What
 * a step costs beyond these and the two ends' work is waiting: the socket's and the threads' wake-ups. Thread-safe.
 */
public final class LinkCosts {
    private final LongAdder sampling = new LongAdder();
    private final LongAdder encoding = new LongAdder();
    private final LongAdder writing = new LongAdder();
    private final LongAdder decoding = new LongAdder();
    private final LongAdder waiting = new LongAdder();

    public void addSampling(long nanos) {
        sampling.add(nanos);
    }

    public void addEncoding(long nanos) {
        encoding.add(nanos);
    }

    public void addWriting(long nanos) {
        writing.add(nanos);
    }

    public void addDecoding(long nanos) {
        decoding.add(nanos);
    }

    /** The controller's lockstep wait for the agent's answer (reading it included), on the simulation thread. */
    public void addWaiting(long nanos) {
        waiting.add(nanos);
    }

    public long samplingNanos() {
        return sampling.sum();
    }

    public long encodingNanos() {
        return encoding.sum();
    }

    public long writingNanos() {
        return writing.sum();
    }

    public long decodingNanos() {
        return decoding.sum();
    }

    public long waitingNanos() {
        return waiting.sum();
    }
}
