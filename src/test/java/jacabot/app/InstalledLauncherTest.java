package jacabot.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.bench.InterpreterBenchmark;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The installed launcher ({@code gradle installDist}, which the tests depend on) from an empty
 * folder outside the repository: experiment names resolve inside the installation, outputs go
 * to the current folder, and --world paths are relative to it.
 */
class InstalledLauncherTest {
    private static Path launcher() {
        String dir = System.getProperty("jacabot.installDir");
        Path bin = dir == null ? null : Path.of(dir, "bin", "jacabot");
        Assumptions.assumeTrue(bin != null && Files.isExecutable(bin),
                "no installed launcher (run `gradle installDist`): the launcher test did not run");
        return bin;
    }

    private static String run(Path cwd, String... args) throws IOException, InterruptedException {
        return run(launcher(), null, cwd, args);
    }

    /** Runs a launcher with JAVA_OPTS set (unless null) and returns its output, checking it exits with 0. */
    private static String run(Path launcher, String javaOptions, Path cwd, String... args) throws IOException, InterruptedException {
        var cmd = new ArrayList<String>(List.of(launcher.toString()));
        cmd.addAll(List.of(args));
        var builder = new ProcessBuilder(cmd).directory(cwd.toFile()).redirectErrorStream(true);
        if (javaOptions != null) {
            builder.environment().put("JAVA_OPTS", javaOptions);
        }
        Process p = builder.start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the launcher did not end:\n" + out);
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    @Test
    void theLauncherMapsItsClassDataSharingArchiveAndRunsQuietlyWhenItCannot(@TempDir Path dir) throws Exception {
        Path home = launcher().getParent().getParent();
        assertTrue(Files.isRegularFile(home.resolve("lib/jacabot.jsa")), "installDist made no archive (see build/tmp/cds/training.log)");
        Files.writeString(dir.resolve("hello.asl"), "!start.\n+!start <- .print(\"hello world\"); .stopMAS.\n");
        // -Xshare:on: a JVM that cannot map the archive stops instead of running on without it
        assertEquals("[hello] hello world\n", run(launcher(), "-Xshare:on", dir, "run", "hello.asl"));
        // a moved installation: the archive names other jars, so the JVM runs without it, and says nothing
        Path moved = dir.resolve("moved");
        for (String sub : List.of("bin", "lib")) {
            Files.createDirectories(moved.resolve(sub));
            try (var files = Files.list(home.resolve(sub))) {
                for (Path f : files.toList()) {
                    Files.copy(f, moved.resolve(sub).resolve(f.getFileName()), StandardCopyOption.COPY_ATTRIBUTES);
                }
            }
        }
        assertEquals("[hello] hello world\n", run(moved.resolve("bin/jacabot"), null, dir, "run", "hello.asl"));
    }

    @Test
    void anExperimentMapsItsOwnArchiveWithTheWorldsClasses(@TempDir Path dir) throws Exception {
        Path home = launcher().getParent().getParent();
        assertTrue(Files.isRegularFile(home.resolve("lib/jacabot-experiment.jsa")),
                "installDist made no experiment archive (see build/tmp/cds/experiment-training.log)");
        String out = run(launcher(), "-Xshare:on -Xlog:class+load", dir, "experiment", "navigation", "--headless",
                "--duration", "1s", "--out", "run");
        // the world's physics is in the experiment's archive, not in the AgentSpeak programs' one
        assertTrue(out.lines().anyMatch(l -> l.contains("org.dyn4j.") && l.contains("shared objects file (top)")), out);
    }

    /**
     * AgentSpeak programs and single experiments start with C1 only, as the interpreter bench measures
     * programs; sweeps, benches and the other commands keep C2.
     */
    @Test
    void runTestAndExperimentStartWithTheBenchsJitOptionAndTheOtherCommandsWithout(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("hello.asl"), "!start.\n+!start <- .print(\"hello world\"); .stopMAS.\n");
        String flags = "-XX:+PrintCommandLineFlags";
        String run = run(launcher(), flags, dir, "--debug", "run", "hello.asl");
        assertTrue(run.contains(InterpreterBenchmark.RUN_JIT) && run.contains("[hello] hello world"), run);
        String test = run(launcher(), flags, dir, "test", "--help");
        assertTrue(test.contains(InterpreterBenchmark.RUN_JIT), test);
        String experiment = run(launcher(), flags, dir, "experiment", "--help");
        assertTrue(experiment.contains(InterpreterBenchmark.RUN_JIT), experiment);
        String world = run(launcher(), flags, dir, "world", "generate", "navigation", "--seed", "1", "--out", "w.json");
        assertTrue(world.contains("-XX:") && !world.contains("TieredStopAtLevel"), world);
        String sweep = run(launcher(), flags, dir, "sweep", "--help");
        assertTrue(sweep.contains("-XX:") && !sweep.contains("TieredStopAtLevel"), sweep);
    }

    @Test
    void experimentRunsFromAnEmptyFolder(@TempDir Path empty) throws Exception {
        String out = run(empty, "experiment", "navigation", "--headless", "--duration", "3s", "--seed", "7");
        Path runDir = empty.resolve("runs/navigation-7");
        for (String f : List.of("summary.json", "event-log.txt", "trajectory.png", "steps.jsonl.gz", "battery.png", "speed.png")) {
            assertTrue(Files.isRegularFile(runDir.resolve(f)), f + " missing in " + runDir + ":\n" + out);
        }
        // the bundled world by its path in the installation (as in a checkout), not this machine's folder
        assertTrue(out.contains("World worlds/navigation.json,") && out.contains("files: world worlds/navigation.json,"), out);
    }

    @Test
    void worldAndAgentPathsAreRelativeToTheCurrentFolder(@TempDir Path dir) throws Exception {
        Path home = launcher().getParent().getParent();
        Files.copy(home.resolve("worlds/navigation.json"), dir.resolve("my-world.json"));
        Files.copy(home.resolve("agents/src/main/asl/navigation.asl"), dir.resolve("my-agent.asl"));
        String out = run(dir, "experiment", "navigation", "--headless", "--duration", "1s", "--world", "my-world.json",
                "--agent", "my-agent.asl", "--out", "out");
        assertTrue(Files.isRegularFile(dir.resolve("out/summary.json")), out);
        assertTrue(out.contains("World my-world.json"), out);
    }

    @Test
    void theDefaultRunIsCalmAndWritesNoLinkLog(@TempDir Path empty) throws Exception {
        String out = run(empty, "experiment", "navigation", "--headless", "--duration", "2s");
        assertTrue(out.startsWith("Experiment 3 (navigation)"), "jacabot's own line first:\n" + out);
        assertTrue(Files.isRegularFile(empty.resolve("runs/navigation-3/steps.jsonl.gz")), out);
        assertTrue(!Files.exists(empty.resolve("runs/navigation-3/link-log.txt")), "no link log unless --link-log");
        String quiet = run(empty, "experiment", "navigation", "--headless", "--duration", "2s", "--quiet");
        assertTrue(quiet.startsWith("run: navigation"), quiet);
    }

    @Test
    void compareBenchAndSweepRunFromAnEmptyFolder(@TempDir Path empty) throws Exception {
        String compare = run(empty, "compare", "--seeds", "1", "--duration", "2s");
        assertEquals(8, compare.lines().filter(l -> l.matches("\\| [a-z-]+ \\| (agent|baseline) \\| 1 \\|.*")).count(), compare);
        // the baselines' code metrics, from the sources bundled with the installation
        assertTrue(compare.lines().anyMatch(l -> l.matches("\\| suspend-resume \\| \\d+ \\| \\d+ \\|.*")), compare);
        String bench = run(empty, "bench", "sim", "--duration", "3s");
        assertTrue(bench.startsWith("Experiment 4 with the agent, lockstep, seed 13, "), "the experiment's seed:\n" + bench);
        String sweep = run(empty, "sweep", "navigation", "--worlds", "worlds", "--seeds", "1", "--duration", "2s",
                "--controllers", "agent", "--jobs", "1", "--no-progress");
        assertTrue(sweep.startsWith("Sweep: 1 run (1 world x 1 seed x 1 controller)"), sweep);
        assertTrue(Files.isRegularFile(empty.resolve("runs/sweep/report.md")), sweep);
    }
}
