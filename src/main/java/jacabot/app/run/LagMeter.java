package jacabot.app.run;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.CircumstanceListener;
import jacabot.agent.semantics.Event;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * How far a real-time (viewer) run falls behind, in simulated time. A run lags in two ways:
 * <ul>
 *   <li>the <b>world</b> falls behind real time: its runner cannot step as fast as the requested
 *       factor asks (simulated time wanted by the wall clock minus simulated time reached);</li>
 *   <li>the <b>agent</b> falls behind the world: it runs free on its own thread, so when it reasons
 *       more slowly than percepts come, its events queue up and the plan it selects now answers an
 *       event posted some simulated time ago (that age is measured per selected event).</li>
 * </ul>
 * A lag episode starts when either exceeds {@link #THRESHOLD_MS} and ends when both are back under
 * half of it (so one slow moment is one episode, not a flicker). {@link #sample()} runs every
 * {@value #PERIOD_MS} ms of wall clock (on a timer thread, {@link #start()}).
 */
public final class LagMeter implements AutoCloseable {
    /** Lag, in simulated milliseconds, that starts an episode. */
    public static final long THRESHOLD_MS = 1000;
    public static final long PERIOD_MS = 250;
    private static final int REMEMBERED_EVENTS = 4096;

    /** One look at the run: lag in simulated ms, the factor asked for and the one measured (NaN before a second). */
    public record Reading(long timeMs, long worldBehindMs, long agentLateMs, double requested, double achieved,
            boolean lagging) {
    }

    /** One lag episode, from its start to its end (or to the end of the run), in simulated ms. */
    public record Episode(long startMs, long endMs, long worstWorldBehindMs, long worstAgentLateMs, double requested,
            double lowestAchieved) {
        /** {@return one line for the console and summary.txt} */
        public String describe() {
            return String.format(Locale.ROOT, "t=%.1f-%.1f s: world up to %.1f s behind real time, agent up to %.1f s late"
                    + " (x%s requested, x%.1f achieved at the lowest)", startMs / 1000.0, endMs / 1000.0,
                    worstWorldBehindMs / 1000.0, worstAgentLateMs / 1000.0, factor(requested),
                    Double.isNaN(lowestAchieved) ? 0.0 : lowestAchieved);
        }
    }

    /** Hears an episode start (with the reading that started it) and end. */
    public interface Listener {
        void started(Reading reading);

        void ended(Episode episode);
    }

    /**
     * {@return a listener that warns once, when the run first lags (later episodes go to the step log
     * and the summary only: a warning per episode would flood the console of a machine that cannot keep up)}
     */
    public static Listener firstWarning(Consumer<String> warn) {
        return new Listener() {
            private boolean warned;

            @Override
            public void started(Reading r) {
                if (!warned) {
                    warned = true;
                    warn.accept(String.format(Locale.ROOT, "at t=%.1f s the run lags: %s. The agent now sees the world late"
                            + " and may act unlike a lockstep run; lower --speed, or use --lockstep for an exact run"
                            + " (further lag is recorded in the step log and summary.txt, not printed)",
                            r.timeMs() / 1000.0, status(r).replace("LAG: ", "").replace('×', 'x')));
                }
            }

            @Override
            public void ended(Episode e) {
            }
        };
    }

    private final SimRunner runner;
    private final SimWorld world;
    private final LongSupplier wallNanos;
    private final List<Listener> listeners = new ArrayList<>();
    private final List<Episode> episodes = new ArrayList<>();
    private final List<Agent> agents = new ArrayList<>();
    /** When (simulated ms) each recent event was posted, by identity: events are records, equal ones differ. */
    private final Map<IdentityKey, Long> posted = new LinkedHashMap<>(64, 0.75f, false) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(Map.Entry<IdentityKey, Long> eldest) {
            return size() > REMEMBERED_EVENTS; // events dropped without a plan are forgotten this way
        }
    };
    private long windowLateMs = -1; // worst age of an event selected since the last sample, -1: none
    private long agentLateMs;
    private long anchorWallNs, anchorSimMs;
    private double anchorSpeed = Double.NaN;
    private long startSimMs = -1;
    private boolean moving;
    private volatile Reading last;
    private Episode open;
    private ScheduledExecutorService timer;

    public LagMeter(SimRunner runner) {
        this(runner, System::nanoTime);
    }

    /** @param wallNanos the wall clock (a test's own) */
    public LagMeter(SimRunner runner, LongSupplier wallNanos) {
        this.runner = runner;
        this.world = runner.world();
        this.wallNanos = wallNanos;
        this.last = new Reading(world.timeMs(), 0, 0, runner.speedFactor(), Double.NaN, false);
    }

    public LagMeter addListener(Listener l) {
        synchronized (this) {
            listeners.add(l);
        }
        return this;
    }

    /** Times {@code agent}'s events from their posting to their plan's selection; call before it runs. */
    public void watch(Agent agent) {
        synchronized (this) {
            agents.add(agent);
        }
        agent.circumstance().addListener(new CircumstanceListener() {
            @Override
            public void eventAdded(Event e) {
                posted(e);
            }
        });
    }

    /** On the agent's thread: {@code e} was posted now. */
    void posted(Event e) {
        long now = world.timeMs();
        synchronized (posted) {
            posted.put(new IdentityKey(e), now);
        }
    }

    /** On the agent's thread: a plan was selected for {@code e} (from the agent's plan listener). */
    public void planSelected(Event e) {
        Long at;
        synchronized (posted) {
            at = posted.remove(new IdentityKey(e));
        }
        if (at != null) {
            long age = world.timeMs() - at;
            synchronized (this) {
                windowLateMs = Math.max(windowLateMs, age);
            }
        }
    }

    /** Samples every {@value #PERIOD_MS} ms on a daemon thread until {@link #close()}. */
    public synchronized LagMeter start() {
        if (timer == null) {
            timer = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "lag-meter");
                t.setDaemon(true);
                return t;
            });
            timer.scheduleAtFixedRate(this::sample, PERIOD_MS, PERIOD_MS, TimeUnit.MILLISECONDS);
        }
        return this;
    }

    /** Looks at the run now: measures, and starts or ends an episode. {@return the reading} */
    public Reading sample() {
        List<Listener> hear;
        Reading r;
        Episode ended = null;
        boolean startedNow = false;
        synchronized (this) {
            long now = wallNanos.getAsLong();
            long sim = world.timeMs();
            double speed = runner.speedFactor();
            if (!moving) {
                // until the world first moves (the controller is still connecting, the agent starting)
                // there is no schedule to keep, and the first move starts it
                moving = startSimMs >= 0 && sim > startSimMs;
                startSimMs = startSimMs < 0 ? sim : startSimMs;
                anchorSpeed = Double.NaN; // so the schedule is anchored below, at the first move too
            }
            boolean paced = runner.mode() == SimRunner.Mode.REAL_TIME && !runner.isPaused();
            long behind = 0;
            if (!paced || speed != anchorSpeed) {
                anchor(now, sim, speed); // paused, stepping, "fast" or a new factor: a new schedule
            } else {
                behind = Math.round((now - anchorWallNs) / 1e6 * speed) - (sim - anchorSimMs);
                if (behind < 0) {
                    anchor(now, sim, speed); // ahead of this schedule: the runner's pacing waits; start it here
                    behind = 0;
                }
            }
            if (windowLateMs >= 0) {
                agentLateMs = windowLateMs;
            } else if (agentsIdle()) {
                agentLateMs = 0; // nothing left to answer: not behind
            } // else: busy without a selection since the last look, keep the last figure
            windowLateMs = -1;
            double achieved = runner.realTimeFactor();
            boolean lagging = open == null ? behind > THRESHOLD_MS || agentLateMs > THRESHOLD_MS
                    : behind > THRESHOLD_MS / 2 || agentLateMs > THRESHOLD_MS / 2;
            r = new Reading(sim, behind, agentLateMs, speed, achieved, lagging);
            last = r;
            if (lagging && open == null) {
                open = new Episode(sim, sim, behind, agentLateMs, speed, achieved);
                startedNow = true;
            } else if (lagging) {
                open = new Episode(open.startMs(), sim, Math.max(open.worstWorldBehindMs(), behind),
                        Math.max(open.worstAgentLateMs(), agentLateMs), open.requested(), min(open.lowestAchieved(), achieved));
            } else if (open != null) {
                ended = new Episode(open.startMs(), sim, open.worstWorldBehindMs(), open.worstAgentLateMs(),
                        open.requested(), open.lowestAchieved());
                episodes.add(ended);
                open = null;
            }
            hear = List.copyOf(listeners);
        }
        for (Listener l : hear) {
            if (startedNow) {
                l.started(r);
            }
            if (ended != null) {
                l.ended(ended);
            }
        }
        return r;
    }

    private static double min(double a, double b) {
        return Double.isNaN(a) ? b : Double.isNaN(b) ? a : Math.min(a, b);
    }

    private void anchor(long wallNs, long simMs, double speed) {
        anchorWallNs = wallNs;
        anchorSimMs = simMs;
        anchorSpeed = speed;
    }

    private boolean agentsIdle() {
        for (Agent a : agents) {
            try {
                if (!a.canSleep()) {
                    return false;
                }
            } catch (RuntimeException e) {
                return false; // read off the agent's thread: not sure, so not idle
            }
        }
        return true;
    }

    /** {@return the last reading} */
    public Reading last() {
        return last;
    }

    /** {@return the status line's words for the lag now, or "" when the run keeps up} */
    public String status() {
        return status(last);
    }

    /** {@return e.g. "LAG: world 1.2 s behind real time (×16 requested, ×9.3 achieved); agent 2.3 s behind", "" when keeping up} */
    public static String status(Reading r) {
        if (!r.lagging()) {
            return "";
        }
        var parts = new ArrayList<String>();
        if (r.worldBehindMs() > THRESHOLD_MS / 2) {
            parts.add(String.format(Locale.ROOT, "world %.1f s behind real time (×%s requested%s)", r.worldBehindMs() / 1000.0,
                    factor(r.requested()), Double.isNaN(r.achieved()) ? "" // before the runner's first second
                            : String.format(Locale.ROOT, ", ×%.1f achieved", r.achieved())));
        }
        if (r.agentLateMs() > THRESHOLD_MS / 2) {
            parts.add(String.format(Locale.ROOT, "agent %.1f s behind the world", r.agentLateMs() / 1000.0));
        }
        return parts.isEmpty() ? "lagging" : "LAG: " + String.join("; ", parts);
    }

    private static String factor(double f) {
        return f == Math.rint(f) ? String.valueOf((long) f) : String.format(Locale.ROOT, "%.2f", f);
    }

    /** {@return the episodes so far, the open one included (ending now)} */
    public synchronized List<Episode> episodes() {
        var all = new ArrayList<>(episodes);
        if (open != null) {
            all.add(open);
        }
        return all;
    }

    /** Stops sampling; an open episode ends here (its listeners hear it). */
    @Override
    public void close() {
        Episode ended = null;
        List<Listener> hear;
        synchronized (this) {
            if (timer != null) {
                timer.shutdownNow();
                timer = null;
            }
            if (open != null) {
                ended = open;
                episodes.add(open);
                open = null;
            }
            hear = List.copyOf(listeners);
        }
        if (ended != null) {
            for (Listener l : hear) {
                l.ended(ended);
            }
        }
    }

    /** An event by identity (events are records: two equal triggers are still two events). */
    private static final class IdentityKey {
        private final Event event;

        IdentityKey(Event event) {
            this.event = event;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof IdentityKey k && k.event == event;
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(event);
        }
    }
}
