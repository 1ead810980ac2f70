package jacabot.agent.semantics;

import java.util.PriorityQueue;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * The tasks an agent runs at the start of a reasoning cycle's deliberation: those asked for the
 * next cycle (any thread, as Jason's {@code runAtBeginOfNextCycle}) and timers that join them once
 * the agent's clock reaches their time ({@code .wait}, {@code .at}). Timers due at the same
 * time fire in the order they were set.
 */
final class CycleTasks {
    private record Timer(long due, long seq, Runnable task) implements Comparable<Timer> {
        @Override
        public int compareTo(Timer o) {
            return due != o.due ? Long.compare(due, o.due) : Long.compare(seq, o.seq);
        }
    }

    private final ConcurrentLinkedQueue<Runnable> next = new ConcurrentLinkedQueue<>();
    private final PriorityQueue<Timer> timers = new PriorityQueue<>();
    /** Whether {@code timers} may hold a timer: every cycle checks it without taking the lock. */
    private volatile boolean hasTimers;
    private long timerSerial;

    /** Asks for {@code task} at the start of the next cycle (any thread). */
    void add(Runnable task) {
        next.add(task);
    }

    /** {@return whether no task waits for the next cycle (timers not due aside)} */
    boolean isEmpty() {
        return next.isEmpty();
    }

    /** Runs the tasks asked for, in order, those they ask for included. */
    void runAll() {
        Runnable r;
        while ((r = next.poll()) != null) {
            r.run();
        }
    }

    /** Sets a timer: {@code task} joins the next cycle's tasks once the clock reaches {@code due} (ms). */
    synchronized void schedule(long due, Runnable task) {
        timers.add(new Timer(due, timerSerial++, task));
        hasTimers = true;
    }

    /** {@return when the earliest timer is due, or {@code Long.MAX_VALUE}} */
    synchronized long nextDue() {
        Timer t = timers.peek();
        return t == null ? Long.MAX_VALUE : t.due;
    }

    /** Moves the timers due by the clock's time to this cycle's tasks (the clock is read only when a timer is set). */
    void fireDue(Clock clock) {
        if (!hasTimers) {
            return;
        }
        synchronized (this) {
            if (timers.isEmpty()) {
                hasTimers = false;
                return;
            }
        }
        long now = clock.millis();
        while (true) {
            Timer t;
            synchronized (this) {
                t = timers.peek();
                if (t == null || t.due > now) {
                    return;
                }
                timers.poll();
            }
            next.add(t.task);
        }
    }
}
