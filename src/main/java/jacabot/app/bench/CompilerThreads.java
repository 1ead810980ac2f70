package jacabot.app.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/**
 * The CPU time of this JVM's JIT compiler threads ({@code C1 CompilerThread0}, {@code C2 ...}),
 * so that a bench tells compiling apart from the run's own cost: on two cores the compilers take
 * as much CPU as a run's threads while a run is young. Read from Linux's per-thread accounting
 * ({@code /proc/self/task/TID/stat}, user and system time in clock ticks of 10 ms); the JDK's
 * {@code CompilationMXBean} gives compiling's elapsed time instead, which on a loaded machine
 * counts the time a compiler thread waited for a core.
 */
final class CompilerThreads {
    /** Linux's clock tick for {@code /proc} times ({@code getconf CLK_TCK}: 100 on every usual kernel). */
    private static final long TICK_NANOS = 10_000_000;
    private static final Path TASKS = Path.of("/proc/self/task");

    private CompilerThreads() {
    }

    /** {@return the compiler threads' CPU so far in nanoseconds, or -1 where {@code /proc} does not tell} */
    static long cpuNanos() {
        if (!Files.isDirectory(TASKS)) {
            return -1;
        }
        long ticks = 0;
        try (Stream<Path> tasks = Files.list(TASKS)) {
            for (Path t : (Iterable<Path>) tasks::iterator) {
                ticks += compilerTicks(t.resolve("stat"));
            }
        } catch (IOException | RuntimeException e) {
            return -1;
        }
        return ticks * TICK_NANOS;
    }

    /** {@return the user and system ticks of the thread whose {@code stat} this is, when it is a compiler; else 0} */
    private static long compilerTicks(Path stat) {
        String line;
        try {
            line = Files.readString(stat);
        } catch (IOException e) {
            return 0; // the thread ended since the listing
        }
        return compilerTicks(line);
    }

    /** The same, from the text of a {@code stat} file: {@code TID (NAME) STATE ...}, utime and stime its 14th and 15th fields. */
    static long compilerTicks(String stat) {
        int open = stat.indexOf('(');
        int close = stat.lastIndexOf(')');
        if (open < 0 || close < open) {
            return 0;
        }
        String name = stat.substring(open + 1, close);
        if (!name.startsWith("C1 Compiler") && !name.startsWith("C2 Compiler")) {
            return 0;
        }
        String[] f = stat.substring(close + 2).split(" ");
        return Long.parseLong(f[11]) + Long.parseLong(f[12]);
    }
}
