package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * Records what an agent perceives as lines such as {@code c0 count(0)->count(1)} or
 * {@code c0 !tick}; tests read them in order.
 */
final class RecordingObserver implements ArtifactObserver {
    private final BlockingQueue<String> events = new LinkedBlockingQueue<>();
    private final List<String> all = new ArrayList<>();

    private synchronized void record(String event) {
        all.add(event);
        events.add(event);
    }

    @Override
    public void focused(ArtifactId artifact, List<PropertySnapshot> properties) {
        record(artifact.name() + " focused " + properties);
    }

    @Override
    public void propertyAdded(ArtifactId artifact, PropertySnapshot property) {
        record(artifact.name() + " +" + property);
    }

    @Override
    public void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue) {
        record(artifact.name() + " " + oldValue + "->" + newValue);
    }

    @Override
    public void propertyRemoved(ArtifactId artifact, PropertySnapshot property) {
        record(artifact.name() + " -" + property);
    }

    @Override
    public void signalled(ArtifactId artifact, String type, List<Object> args) {
        record(artifact.name() + " !" + type + (args.isEmpty() ? "" : args.toString()));
    }

    @Override
    public void focusEnded(ArtifactId artifact, List<PropertySnapshot> properties, boolean disposed) {
        record(artifact.name() + (disposed ? " disposed " : " unfocused ") + properties);
    }

    /** {@return the next event, waiting up to 10 s (a safety net, not a timing assumption)} */
    String next() {
        try {
            String event = events.poll(10, TimeUnit.SECONDS);
            if (event == null) {
                fail("no event within 10 s; seen so far: " + seen());
            }
            return event;
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
    }

    /** Asserts the next events, in order. */
    void expect(String... expected) {
        for (String e : expected) {
            assertEquals(e, next());
        }
    }

    /** Skips events until {@code expected} comes. */
    void skipUntil(String expected) {
        while (!next().equals(expected)) {
            // skip
        }
    }

    /** {@return the events not read yet, without waiting} */
    List<String> drain() {
        List<String> rest = new ArrayList<>();
        events.drainTo(rest);
        return rest;
    }

    /** {@return every event recorded so far} */
    synchronized List<String> seen() {
        return new ArrayList<>(all);
    }
}
