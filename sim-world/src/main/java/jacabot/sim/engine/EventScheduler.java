package jacabot.sim.engine;

import jacabot.sim.world.EventSpec;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

/** Fires the world file's scripted events, each once, in file order when several are due together. Internal. */
final class EventScheduler {
    private static final class Pending {
        final EventSpec spec;
        long dueMs = -1; // known once the trigger has held

        Pending(EventSpec spec) {
            this.spec = spec;
        }
    }

    private final List<Pending> pending = new ArrayList<>();

    EventScheduler(List<EventSpec> events) {
        for (EventSpec e : events) {
            Pending p = new Pending(e);
            if (e.trigger() instanceof EventSpec.At at) {
                p.dueMs = toMs(at.seconds() + e.after());
            }
            pending.add(p);
        }
    }

    private static long toMs(double seconds) {
        return Math.round(seconds * 1000.0);
    }

    /** Checks triggers and performs the events due at {@code nowMs}. */
    void update(long nowMs, Engine engine) {
        for (Iterator<Pending> it = pending.iterator(); it.hasNext(); ) {
            Pending p = it.next();
            if (p.dueMs < 0 && p.spec.trigger() instanceof EventSpec.Near near && engine.isNear(near)) {
                p.dueMs = nowMs + toMs(p.spec.after());
            }
            if (p.dueMs >= 0 && nowMs >= p.dueMs) {
                it.remove();
                engine.perform(p.spec.action());
            }
        }
    }

    /** {@return how many events have not fired yet} */
    int remaining() {
        return pending.size();
    }
}
