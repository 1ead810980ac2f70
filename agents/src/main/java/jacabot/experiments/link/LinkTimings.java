package jacabot.experiments.link;

import jacabot.robot.link.Command;
import jacabot.robot.link.LinkClock;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;

/**
 * The timestamps of the thesis' performance analysis (Chapter 5 §3), taken on both sides of the
 * link with the shared {@link LinkClock}:
 * <ul>
 *   <li><b>transport</b>: reading sampled by the controller → read off the socket here;</li>
 *   <li><b>delivery</b>: reading sampled → handed out by {@link MiddlewareLink#receive()};</li>
 *   <li><b>reactive</b>: reading sampled → the plan it triggers is selected, recorded by the agent
 *       side with {@link #planTriggered(LinkEvent.Reading)};</li>
 *   <li><b>response</b>: action executed by the agent ({@link MiddlewareLink#send(Command, long)})
 *       → the controller applied it to the actuators (its {@code APPLIED} report).</li>
 * </ul>
 */
public final class LinkTimings {
    private static final int CAPACITY = 100_000;

    private final LinkClock clock;
    private final LatencyRecorder transport = new LatencyRecorder(CAPACITY);
    private final LatencyRecorder delivery = new LatencyRecorder(CAPACITY);
    private final LatencyRecorder reactive = new LatencyRecorder(CAPACITY);
    private final LatencyRecorder response = new LatencyRecorder(CAPACITY);
    private final LongAdder answered = new LongAdder();
    private final AtomicLong maxStepsLate = new AtomicLong();

    LinkTimings(LinkClock clock) {
        this.clock = clock;
    }

    /** The agent side: the plan reacting to this reading was triggered now. */
    public void planTriggered(LinkEvent.Reading reading) {
        reactive.record(clock.nowMicros() - reading.sampledMicros());
    }

    /** Forgets every sample so far: a benchmark's warm-up is over. */
    public void clear() {
        transport.clear();
        delivery.clear();
        reactive.clear();
        response.clear();
        answered.reset();
        maxStepsLate.set(0);
    }

    public LatencyStats transport() {
        return transport.stats();
    }

    public LatencyStats delivery() {
        return delivery.stats();
    }

    public LatencyStats reactive() {
        return reactive.stats();
    }

    /** {@return the response times kept, in microseconds (for a histogram)} */
    public long[] responseSamples() {
        return response.samples();
    }

    public LatencyStats response() {
        return response.stats();
    }

    void received(LinkEvent.Reading r) {
        transport.record(r.receivedMicros() - r.sampledMicros());
    }

    void delivered(LinkEvent.Reading r) {
        delivery.record(clock.nowMicros() - r.sampledMicros());
    }

    void applied(long actionMicros, long appliedMicros) {
        response.record(appliedMicros - actionMicros);
    }

    /** Lockstep: a command that answered step k was applied at step k + {@code steps}. */
    void appliedSteps(long steps) {
        answered.increment();
        maxStepsLate.accumulateAndGet(steps, Math::max);
    }

    /** {@return how many lockstep answers the controller reported applied} */
    public long lockstepApplied() {
        return answered.sum();
    }

    /** {@return the most control steps between a lockstep answer's step and the step it was applied at} */
    public long maxStepsLate() {
        return maxStepsLate.get();
    }

    @Override
    public String toString() {
        return "transport " + transport() + "; delivery " + delivery() + "; reactive " + reactive() + "; response " + response();
    }
}
