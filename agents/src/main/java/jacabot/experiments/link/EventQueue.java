package jacabot.experiments.link;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingDeque;
import java.util.concurrent.LinkedBlockingDeque;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * The link's events on their way to the middleware: a bounded queue that {@link MiddlewareLink#receive()}
 * takes from (one {@code await(IBlockingCmd)} of the artifact, thesis Chapter 3 §2.4), or, after
 * {@link #handOver}, a handler called on the connection's reading thread. When nobody reads, the
 * oldest readings make room; a connection event is never dropped.
 */
final class EventQueue {
    private final BlockingDeque<LinkEvent> events = new LinkedBlockingDeque<>();
    private final int capacity;
    private final LinkTimings timings;
    /** Orders the hand-over against events arriving meanwhile. */
    private final Object dispatch = new Object();
    /** Set by {@link #handOver}: events go to it, not to the queue. */
    private Consumer<LinkEvent> handler;

    EventQueue(int capacity, LinkTimings timings) {
        this.capacity = capacity;
        this.timings = timings;
    }

    LinkEvent take() throws InterruptedException {
        return delivered(events.take());
    }

    LinkEvent poll(long timeout, TimeUnit unit) throws InterruptedException {
        return delivered(events.poll(timeout, unit));
    }

    /** From now on every event goes to {@code handler}, in order; the events already queued go first. */
    void handOver(Consumer<LinkEvent> newHandler) {
        synchronized (dispatch) {
            for (LinkEvent e = events.poll(); e != null; e = events.poll()) {
                newHandler.accept(delivered(e));
            }
            this.handler = newHandler;
        }
    }

    /** Passes an event on: to the handler if there is one, else into the queue. */
    void dispatch(LinkEvent e) {
        synchronized (dispatch) {
            if (handler != null) {
                handler.accept(delivered(e));
                return;
            }
            if (e instanceof LinkEvent.Reading || e instanceof LinkEvent.StepMarker || e instanceof LinkEvent.FailSafe) {
                enqueue(e);
            } else {
                events.add(e); // connection changes are never dropped
            }
        }
    }

    /** The delivery time of a reading runs to the moment it is handed out. */
    private LinkEvent delivered(LinkEvent e) {
        if (e instanceof LinkEvent.Reading) {
            timings.delivered((LinkEvent.Reading) e);
        }
        return e;
    }

    /** Bounded: when nobody reads, the oldest readings make room (connection events always stay). */
    private void enqueue(LinkEvent e) {
        if (events.size() >= capacity) {
            List<LinkEvent> kept = new ArrayList<>();
            LinkEvent old;
            while (events.size() >= capacity / 2 && (old = events.poll()) != null) {
                if (old instanceof LinkEvent.Connected || old instanceof LinkEvent.Disconnected) {
                    kept.add(old);
                }
            }
            for (int i = kept.size() - 1; i >= 0; i--) {
                events.addFirst(kept.get(i));
            }
        }
        events.add(e);
    }
}
