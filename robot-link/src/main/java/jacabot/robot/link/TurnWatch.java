package jacabot.robot.link;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.function.LongSupplier;

/**
 * Whether the simulation thread should go on taking the middleware's turns ({@link LockstepTurn}).
 * The turns save the two thread wake-ups of every step: what a step costs beyond its work on a
 * quiet machine. On a machine busy with other work it is the other way round: a thread that never
 * blocks gets a smaller share of a core than two threads that block in turn (measured with
 * {@code bench sim} at load 33: the agent's run at 0.19 of the baseline's speed with the turns and
 * 0.86 with the two reading threads, for the same CPU time per step). So the thread measures the
 * share of a core it gets while taking turns, its CPU time over the wall time of each window of
 * {@link #WINDOW} turns (long enough that a garbage collection's pause does not count); after two
 * windows in a row below {@link #MIN_SHARE} it stops taking turns for the rest of the connection.
 * The threshold is a judgement, not a measured crossover: a thread short of a core by more than
 * that shares it with other work, and there the two threads were measured far ahead. The run is the
 * same either way, to the byte: only the thread that reads the middleware's end changes.
 *
 * <p>One instance per simulation thread; not thread-safe.
 */
public final class TurnWatch {
    static final int WINDOW = 1_000;
    /** {@code -Djacabot.turns.minShare=0} keeps the turns whatever the share: to measure them on a loaded machine. */
    private static final double DEFAULT_MIN_SHARE = 0.7;
    static final double MIN_SHARE = minShare(System.getProperty("jacabot.turns.minShare"));

    private final LongSupplier threadCpuNanos;
    private final LongSupplier nanoTime;
    private long turns;
    private int lowWindows;
    private long cpu0, wall0;
    private boolean stopped;

    /** Watches the calling thread's CPU time (turns never stop where the JVM cannot measure it). */
    public TurnWatch() {
        this(threadCpu(), System::nanoTime);
    }

    TurnWatch(LongSupplier threadCpuNanos, LongSupplier nanoTime) {
        this.threadCpuNanos = threadCpuNanos;
        this.nanoTime = nanoTime;
    }

    /** The threshold a measurer set, or 0.7; a value that is no share from 0 to 1 is said and ignored. */
    static double minShare(String set) {
        if (set == null) {
            return DEFAULT_MIN_SHARE;
        }
        try {
            double share = Double.parseDouble(set.trim());
            if (share >= 0 && share <= 1) {
                return share;
            }
        } catch (NumberFormatException notANumber) {
            // said below
        }
        System.err.println("jacabot.turns.minShare: '" + set + "' is no share from 0 to 1; " + DEFAULT_MIN_SHARE + " is used");
        return DEFAULT_MIN_SHARE;
    }

    private static LongSupplier threadCpu() {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        return threads.isCurrentThreadCpuTimeSupported() ? threads::getCurrentThreadCpuTime : () -> -1;
    }

    /** {@return whether to take the middleware's turn of this step} */
    public boolean takes() {
        return !stopped;
    }

    /** Counts a turn taken; {@return true when turns stop from now on (release them)} */
    public boolean taken() {
        if (stopped || turns++ % WINDOW != 0) {
            return false;
        }
        long cpu = threadCpuNanos.getAsLong();
        long wall = nanoTime.getAsLong();
        if (cpu < 0) {
            return false; // not measurable here
        }
        if (turns > 1) {
            double share = (double) (cpu - cpu0) / Math.max(1, wall - wall0);
            lowWindows = share < MIN_SHARE ? lowWindows + 1 : 0;
            stopped = lowWindows >= 2;
        }
        cpu0 = cpu;
        wall0 = wall;
        return stopped;
    }
}
