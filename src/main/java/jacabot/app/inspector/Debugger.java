package jacabot.app.inspector;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Breakpoints and stepping for a lockstep run. The run's thread calls {@link #afterStep} after
 * each control step, once the agent is idle and its mind captured; on a breakpoint (or after a
 * step asked for) that call blocks until {@link #resume} or {@link #step}, from the console or
 * the inspector's page. Nothing in the simulated world moves while it blocks, so a run paused and
 * continued is the same, byte for byte, as a run never paused. Breakpoints are checked once per
 * control step (the reasoning cycles of a step run together, in lockstep, before the world moves
 * again); {@link #stepCycle} goes one reasoning cycle on: the run calls {@link #beforeCycle} at
 * the start of each cycle, between two cycles, and halts there once a cycle has run.
 */
public final class Debugger {
    /** Where a halted run stands: its time, why it halted, and the agent's mind then. */
    public record Halt(long timeMs, String reason, MindState mind) {
    }

    /**
     * What a page shows of the debugger, read at one instant: where the run is halted (or null)
     * and the breakpoints, with a version that grows at every change of either. A page that gets
     * a command's answer after a newer pushed state (the run halted again meanwhile) keeps the
     * newer one: it never shows a state older than the one it shows.
     */
    public record State(long version, Halt halted, List<String> breakpoints) {
    }

    private final List<Breakpoint> breakpoints = new CopyOnWriteArrayList<>();
    private final List<Consumer<Halt>> listeners = new CopyOnWriteArrayList<>();
    /** The plan labels a {@code label:} breakpoint is checked against (none known: any label is taken). */
    private volatile Supplier<Collection<String>> labels = () -> null;
    private Set<String> beliefs = new HashSet<>();
    private Halt halted;
    /** The halt is at the start of a reasoning cycle (that cycle runs first when the run goes on). */
    private boolean haltedBeforeCycle;
    /** Grows at each change of {@link #state()}. */
    private long version;
    private final Queue<Runnable> tasks = new ArrayDeque<>();
    private boolean stepping;
    /** A one-cycle step was asked for; {@code cycleRan}: its cycle has started. */
    private boolean cycleStepping;
    private boolean cycleRan;
    private boolean pauseAsked;
    private boolean stopped;

    /**
     * Where the agents' plan labels come from (read at each breakpoint added: a reload may change
     * them): a {@code label:} breakpoint that no plan has would never halt the run.
     */
    public void labels(Supplier<Collection<String>> labels) {
        this.labels = labels;
    }

    /**
     * Adds a breakpoint. {@return it}
     *
     * @throws IllegalArgumentException when it does not parse, or names a label no plan has
     */
    public Breakpoint add(String spec) {
        Breakpoint b = Breakpoint.parse(spec);
        String why = b.missingLabel(labels.get());
        if (why != null) {
            throw new IllegalArgumentException(why);
        }
        synchronized (this) {
            breakpoints.add(b);
            version++;
        }
        return b;
    }

    /** Removes the breakpoint with this text. {@return whether there was one} */
    public synchronized boolean remove(String spec) {
        version++;
        return breakpoints.removeIf(b -> b.text().equals(spec.trim()));
    }

    public List<Breakpoint> breakpoints() {
        return List.copyOf(breakpoints);
    }

    /** Calls {@code listener} on the run's thread each time the run halts (print the mind, tell the page). */
    public void onHalt(Consumer<Halt> listener) {
        listeners.add(listener);
    }

    /** {@return where the run is halted and the breakpoints, at one instant} */
    public synchronized State state() {
        return new State(version, halted, breakpoints.stream().map(Breakpoint::text).toList());
    }

    /** {@return where the run is halted, or null while it runs} */
    public synchronized Halt halted() {
        return halted;
    }

    /** Waits until the run halts. {@return where} */
    public synchronized Halt awaitHalt() throws InterruptedException {
        while (halted == null) {
            wait();
        }
        return halted;
    }

    /** Continues a halted run. */
    public synchronized void resume() {
        stepping = false;
        cycleStepping = false;
        halted = null;
        version++;
        notifyAll();
    }

    /** Runs one more control step, then halts again. */
    public synchronized void step() {
        stepping = true;
        cycleStepping = false;
        halted = null;
        version++;
        notifyAll();
    }

    /**
     * Runs one more reasoning cycle, then halts again: before the next cycle, or at the end of the
     * control step when the agent is idle after it (an idle agent's next cycle may be steps away).
     */
    public synchronized void stepCycle() {
        stepping = false;
        cycleStepping = true;
        // halted at the start of a cycle: that cycle is the one step (not it and the next)
        cycleRan = halted != null && haltedBeforeCycle;
        halted = null;
        version++;
        notifyAll();
    }

    /** Halts the run after its current step. */
    public synchronized void pause() {
        pauseAsked = true;
    }

    /** Lets the run go for good (the user quits): never halts again. */
    public synchronized void detach() {
        stopped = true;
        resume();
    }

    /** On the run's thread, after a step: halts there when a breakpoint is hit or a step was asked for. */
    public void afterStep(MindState mind) {
        var now = new HashSet<String>();
        mind.beliefs().forEach(b -> now.add(b.text()));
        var added = new ArrayList<String>();
        for (String b : now) {
            if (!beliefs.contains(b)) {
                added.add(b);
            }
        }
        var removed = new ArrayList<String>();
        for (String b : beliefs) {
            if (!now.contains(b)) {
                removed.add(b);
            }
        }
        added.sort(null);
        removed.sort(null);
        beliefs = now;
        String reason = null;
        synchronized (this) {
            if (stopped) {
                return;
            }
            if (stepping) {
                reason = "one step";
            } else if (pauseAsked) {
                reason = "paused";
            } else if (cycleStepping && cycleRan) {
                reason = "one reasoning cycle (cycle " + mind.cycle() + ", the last of this control step)";
            }
            pauseAsked = false;
        }
        for (Breakpoint b : breakpoints) {
            String why = b.hit(mind, added, removed);
            if (why != null) {
                reason = "breakpoint " + b.text() + ": " + why;
                if (b.kind().equals("time")) {
                    synchronized (this) {
                        breakpoints.remove(b); // a time is reached once
                        version++;
                    }
                }
                break;
            }
        }
        if (reason != null) {
            halt(new Halt(mind.timeMs(), reason, mind), false);
        }
    }

    /**
     * On the run's thread, at the start of a reasoning cycle: halts there when a one-cycle step
     * has had its cycle.
     *
     * @param mind the agent's mind then (asked for only when the run halts)
     */
    public void beforeCycle(Supplier<MindState> mind) {
        synchronized (this) {
            if (stopped || !cycleStepping) {
                return;
            }
            if (!cycleRan) {
                cycleRan = true;
                return;
            }
        }
        MindState m = mind.get();
        halt(new Halt(m.timeMs(), "one reasoning cycle (cycle " + m.cycle() + ")", m), true);
    }

    /** Tells the listeners, then blocks the run's thread until a command lets it go on. */
    private void halt(Halt h, boolean beforeCycle) {
        synchronized (this) {
            stepping = false;
            cycleStepping = false;
        }
        listeners.forEach(l -> l.accept(h)); // before the halt is seen: what they print comes first
        synchronized (this) {
            halted = h;
            haltedBeforeCycle = beforeCycle;
            version++;
            notifyAll();
        }
        // set once: a resume that comes while a task runs (halted = null) must not be overwritten
        while (true) {
            Runnable task;
            synchronized (this) {
                while (halted == h && !stopped && tasks.isEmpty()) {
                    try {
                        wait();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return;
                    }
                }
                if (halted != h || stopped) {
                    return;
                }
                task = tasks.poll();
            }
            task.run(); // on the run's thread, the agent between two cycles
        }
    }

    /**
     * Runs {@code task} on the halted run's thread (the agent between two cycles: e.g. a reload of
     * its plans). {@return when it has run}
     *
     * @throws IllegalStateException when the run is not halted
     */
    public CompletableFuture<Void> atHalt(Runnable task) {
        var done = new CompletableFuture<Void>();
        synchronized (this) {
            if (halted == null || stopped) {
                throw new IllegalStateException("the run is not halted: halt it first (pause or a breakpoint)");
            }
            tasks.add(() -> {
                try {
                    task.run();
                    done.complete(null);
                } catch (RuntimeException e) {
                    done.completeExceptionally(e);
                }
            });
            notifyAll();
        }
        return done;
    }
}
