package jacabot.app.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The bench counts the JIT compiler threads' CPU, and only theirs. */
class CompilerThreadsTest {
    private static String stat(String name, long utime, long stime) {
        return "4242 (" + name + ") S 1 1 0 0 -1 4194304 99 0 0 0 " + utime + " " + stime + " 0 0 20 0 1 0 6296707 3133440 364";
    }

    @Test
    void aCompilerThreadsUserAndSystemTicksAreCounted() {
        assertEquals(57, CompilerThreads.compilerTicks(stat("C2 CompilerThre", 50, 7)));
        assertEquals(3, CompilerThreads.compilerTicks(stat("C1 CompilerThre", 1, 2)));
    }

    @Test
    void otherThreadsCountForNothingEvenWithParenthesesInTheirNames() {
        assertEquals(0, CompilerThreads.compilerTicks(stat("main", 50, 7)));
        assertEquals(0, CompilerThreads.compilerTicks(stat("GC Thread#0", 50, 7)));
        // the name ends at the last parenthesis: a thread may name itself "x) S 1 (C2"
        assertEquals(0, CompilerThreads.compilerTicks(stat("x) S 1 (C2 Compiler", 50, 7)));
        assertEquals(0, CompilerThreads.compilerTicks("garbage"));
    }

    @Test
    void onLinuxTheCountIsReadAndNeverGoesBack() {
        assumeTrue(Files.isDirectory(Path.of("/proc/self/task")), "needs Linux's /proc");
        long before = CompilerThreads.cpuNanos();
        assertTrue(before >= 0, "read from /proc: " + before);
        assertTrue(CompilerThreads.cpuNanos() >= before);
    }
}
