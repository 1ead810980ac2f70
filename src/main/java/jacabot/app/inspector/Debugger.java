package jacabot.app.inspector;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * Breakpoints and stepping for a lockstep run. The run's thread calls {@link #afterStep} after
 * each control step, once the agent is idle and its mind captured; on a breakpoint (or after a
 * step asked for) that call blocks until {@link #resume} or {@link #step}, from the console or
 * the inspector's page. Nothing in the simulated world moves while it blocks, so a run paused and
 * continued is the same, byte for byte, as a run never paused. Granularity: one control step (the
 * reasoning cycles of a step run together, in lockstep, before the world moves again).
 */
public final class Debugger {
    /** Where a halted run stands: its time, why it halted, and the agent's mind then. */
    public record Halt(long timeMs, String reason, MindState mind) {
    }

    private final List<Breakpoint> breakpoints = new CopyOnWriteArrayList<>();
    private final List<Consumer<Halt>> listeners = new CopyOnWriteArrayList<>();
    private Set<String> beliefs = new HashSet<>();
    private Halt halted;
    private boolean stepping;
    private boolean pauseAsked;
    private boolean stopped;

    /** Adds a breakpoint. {@return it} */
    public Breakpoint add(String spec) {
        Breakpoint b = Breakpoint.parse(spec);
        breakpoints.add(b);
        return b;
    }

    /** Removes the breakpoint with this text. {@return whether there was one} */
    public boolean remove(String spec) {
        return breakpoints.removeIf(b -> b.text().equals(spec.trim()));
    }

    public List<Breakpoint> breakpoints() {
        return List.copyOf(breakpoints);
    }

    /** Calls {@code listener} on the run's thread each time the run halts (print the mind, tell the page). */
    public void onHalt(Consumer<Halt> listener) {
        listeners.add(listener);
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
        halted = null;
        notifyAll();
    }

    /** Runs one more control step, then halts again. */
    public synchronized void step() {
        stepping = true;
        halted = null;
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
            }
            pauseAsked = false;
        }
        for (Breakpoint b : breakpoints) {
            String why = b.hit(mind, added, removed);
            if (why != null) {
                reason = "breakpoint " + b.text() + ": " + why;
                if (b.kind().equals("time")) {
                    breakpoints.remove(b); // a time is reached once
                }
                break;
            }
        }
        if (reason == null) {
            return;
        }
        Halt h = new Halt(mind.timeMs(), reason, mind);
        synchronized (this) {
            stepping = false;
        }
        listeners.forEach(l -> l.accept(h)); // before the halt is seen: what they print comes first
        synchronized (this) {
            halted = h;
            notifyAll();
            while (halted == h && !stopped) {
                try {
                    wait();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }
    }
}
