package jacabot.app.run;

import static jacabot.experiments.link.LinkTestSupport.waitFor;
import static jacabot.experiments.link.LinkTestSupport.world;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.experiments.link.LinkTestSupport;
import jacabot.experiments.link.LinkConfig;
import jacabot.experiments.link.LinkEvent;
import jacabot.experiments.link.MiddlewareLink;
import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.Command;
import jacabot.robot.link.LinkSecret;
import java.io.File;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The thesis' two-process set-up with real processes: the agent platform is {@code jacabot run
 * obstacle-avoidance.mas2j} in a JVM of its own, the controller runs here. Its faults (docs/reliability.md):
 * the agent JVM killed, the agent's thread dead; and the lockstep mode that used to deadlock at step 0.
 */
@Timeout(value = 10, unit = TimeUnit.MINUTES) // JVMs started and waited for on conditions (see waitLong)
class ProcessFaultsTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    private static final Pattern STOPPED = Pattern.compile("step (\\d+) t=(\\d+) .*WHEEL_SPEEDS=\\[0\\.0,0\\.0\\].*");

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    /** Starts {@code jacabot run MAS --port P --secret-file F} in a JVM of its own. */
    private static Process agentPlatform(Path mas, int port, Path secret, Path output, String... jvm) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-Xmx256m"));
        cmd.addAll(List.of(jvm));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "jacabot.app.cli.JacabotCommand", "run",
                mas.toString(), "--port", String.valueOf(port), "--secret-file", secret.toString()));
        return new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(output.toFile()).start();
    }

    /** A project like agents/src/main/asl/obstacle-avoidance.mas2j, with another architecture if asked. */
    private static Path project(Path dir, String arch) throws Exception {
        Files.copy(ROOT.resolve("agents/src/main/asl/obstacle-avoidance.asl"), dir.resolve("obstacle-avoidance.asl"));
        // and what it includes: jacabot run finds includes as Jason does, beside the file or on aslSourcePath
        Files.createDirectories(dir.resolve("skills"));
        try (var skills = Files.list(ROOT.resolve("agents/src/main/asl/skills"))) {
            for (Path skill : skills.toList()) {
                Files.copy(skill, dir.resolve("skills").resolve(skill.getFileName()));
            }
        }
        Path mas = dir.resolve("robot.mas2j");
        Files.writeString(mas, "MAS robot {\n infrastructure: Local\n environment: jacabot.cartago.bridge.CartagoEnvironment\n"
                + " agents:\n  robot obstacle-avoidance.asl agentArchClass " + arch + ";\n}\n");
        return mas;
    }

    private static RobotController controller(int port, Path secret, boolean lockstep, List<String> events,
            List<String> log) throws Exception {
        var cc = ControllerConfig.defaults().withAddress("127.0.0.1", port).withSecret(LinkSecret.loadOrCreate(secret))
                .withLockstep(lockstep).withBackoff(50, 200).withEventLog(events::add).withLog(log::add);
        var c = new RobotController(world("obstacle-avoidance"), cc);
        c.start();
        return c;
    }

    /**
     * {@return the simulated ms from {@code fromMs} (when the agent side failed) to the first step at
     * or after it whose wheel speeds reading is (0, 0): when the robot stood still}
     */
    private static long stopDelay(List<String> events, long fromMs) {
        for (String e : events) {
            Matcher m = STOPPED.matcher(e);
            if (m.matches() && Long.parseLong(m.group(2)) >= fromMs) {
                return Long.parseLong(m.group(2)) - fromMs;
            }
        }
        throw new AssertionError("the wheels did not stop after t=" + fromMs + ": "
                + events.subList(Math.max(0, events.size() - 5), events.size()));
    }

    /** Waits up to 240 s: a JVM starting on a loaded machine is slow (at load 43, over 120 s once). */
    private static void waitLong(BooleanSupplier condition) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(240);
        while (!condition.getAsBoolean() && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertTrue(condition.getAsBoolean(), "condition not met within 240 s");
    }

    @Test
    void twoProcessLockstepRunsStepByStep(@TempDir Path dir) throws Exception {
        int port = freePort();
        Path secret = dir.resolve("secret");
        Process agent = agentPlatform(ROOT.resolve("agents/src/main/asl/obstacle-avoidance.mas2j"), port, secret,
                dir.resolve("agent.txt"));
        try {
            waitLong(() -> Files.exists(secret)); // the agent platform made it (0600)
            List<String> events = new CopyOnWriteArrayList<>(), log = new CopyOnWriteArrayList<>();
            try (var c = controller(port, secret, true, events, log)) {
                Thread sim = new Thread(() -> c.runner().runFor(3.0), "two-process-lockstep");
                sim.setDaemon(true);
                sim.start();
                sim.join(TimeUnit.SECONDS.toMillis(180));
                assertTrue(!sim.isAlive(), "3 s of lockstep did not end within 120 s: " + log);
                assertEquals(75, c.steps(), "every step acknowledged: " + log);
                assertTrue(events.stream().anyMatch(e -> e.contains(" apply ")), "the agent drove: "
                        + Files.readString(dir.resolve("agent.txt")) + log + events.subList(0, Math.min(20, events.size())));
            }
        } finally {
            agent.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void theAgentJvmKilledStopsTheRobotWithinAControlStep(@TempDir Path dir) throws Exception {
        int port = freePort();
        Path secret = dir.resolve("secret");
        LinkSecret.loadOrCreate(secret);
        Process agent = agentPlatform(ROOT.resolve("agents/src/main/asl/obstacle-avoidance.mas2j"), port, secret,
                dir.resolve("agent.txt"));
        List<String> events = new CopyOnWriteArrayList<>(), log = new CopyOnWriteArrayList<>();
        try (var c = controller(port, secret, false, events, log)) {
            c.runner().start();
            waitLong(() -> events.stream().anyMatch(e -> e.contains("apply forward") || e.contains("apply setSpeeds"))); // moving
            agent.destroyForcibly(); // SIGKILL: no goodbye
            // the world's time once the kill is issued: read before it, a loaded machine's stall of
            // this thread between the reading and the kill counted against the robot
            long killedAt = c.world().timeMs();
            waitFor(() -> c.failSafeTrips() > 0);
            // the robot cannot know the agent dead before it has read the last of what the agent sent:
            // on a loaded machine that is read after the kill, so the bound counts from the later of the two
            long lastWord = Math.max(killedAt, c.lastHeardSimMs());
            waitFor(() -> events.stream().anyMatch(e -> STOPPED.matcher(e).matches()
                    && Long.parseLong(e.split(" ")[2].substring(2)) >= lastWord));
            long delay = stopDelay(events, lastWord);
            System.out.println("ProcessFaultsTest: agent JVM killed at t=" + killedAt + " ms, last heard from at t="
                    + c.lastHeardSimMs() + " ms, wheels stopped " + delay + " ms of simulated time after the later");
            // docs/reliability.md: within 200 ms of simulated time; the socket's end stops it at the next control
            // step, and failing that the fail-safe, which holds the world rather than overrun: 150 ms of
            // silence and the next 40 ms step, so a loaded machine whose dying JVM closes its socket late
            // stops the robot at 200 ms exactly (seen at load 40), which is within the bound
            assertTrue(delay <= 200, "wheels stopped " + delay + " ms of simulated time after the kill");
            Thread.sleep(200);
            var w = c.robot().getWheels();
            assertEquals(0.0, w.getLeftSpeed());
            assertEquals(0.0, w.getRightSpeed());
            c.runner().stop();
        } finally {
            agent.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void anAgentThreadThatDiesEndsItsProcessWithOneAndTheRobotStops(@TempDir Path dir) throws Exception {
        int port = freePort();
        Path secret = dir.resolve("secret");
        LinkSecret.loadOrCreate(secret);
        Path output = dir.resolve("agent.txt");
        Process agent = agentPlatform(project(dir, DyingArch.class.getName()), port, secret, output,
                "-Djacabot.test.dieAfter=1");
        List<String> events = new CopyOnWriteArrayList<>(), log = new CopyOnWriteArrayList<>();
        try (var c = controller(port, secret, false, events, log)) {
            c.runner().start();
            waitLong(() -> events.stream().anyMatch(e -> e.contains("apply forward") || e.contains("apply setSpeeds"))); // moving
            long movingAt = c.world().timeMs(); // the agent thread dies at its next cycle
            assertTrue(agent.waitFor(60, TimeUnit.SECONDS), "the agent platform did not end");
            long endedAt = c.world().timeMs();
            String said = Files.readString(output, StandardCharsets.UTF_8);
            assertEquals(1, agent.exitValue(), said);
            assertTrue(said.contains("error: thread 'agent-robot' died: StackOverflowError"), said);
            assertTrue(!said.contains("\tat "), "no stack trace without --debug: " + said);
            waitFor(() -> c.failSafeTrips() > 0);
            waitFor(() -> events.stream().anyMatch(e -> STOPPED.matcher(e).matches()
                    && Long.parseLong(e.split(" ")[2].substring(2)) >= movingAt));
            long delay = stopDelay(events, movingAt);
            System.out.println("ProcessFaultsTest: agent thread died after its forward at t=" + movingAt
                    + " ms, process ended with 1 at t=" + endedAt + " ms, wheels stopped " + delay
                    + " ms of simulated time later");
            assertTrue(delay <= 200, "wheels stopped " + delay + " ms of simulated time after the agent's last forward");
            c.runner().stop();
        } finally {
            agent.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void theControllerJvmKilledEndsTheRobotWithItsWorldAndTheAgentSideIsTold(@TempDir Path dir) throws Exception {
        Path secret = dir.resolve("secret");
        var config = LinkConfig.defaults().withPort(0).withSecret(LinkSecret.loadOrCreate(secret))
                .withLog(line -> { });
        try (var m = MiddlewareLink.open(config)) {
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            Process controller = new ProcessBuilder(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                    "jacabot.app.cli.JacabotCommand", "controller", "--world", ROOT.resolve("worlds/navigation.json").toString(),
                    "--port", String.valueOf(m.port()), "--secret-file", secret.toString())
                    .redirectErrorStream(true).redirectOutput(dir.resolve("controller.txt").toFile()).start();
            try {
                waitLong(m::isConnected);
                assertTrue(m.send(Command.forward()));
                LinkTestSupport.await(m, LinkTestSupport.wheels(50, 50));
                long lastSeen = m.simTimeMs();
                controller.destroyForcibly(); // SIGKILL: the world, and the robot in it, end with the process
                long t0 = System.nanoTime();
                var gone = (LinkEvent.Disconnected) LinkTestSupport.await(m,
                        e -> e instanceof LinkEvent.Disconnected);
                long ms = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0);
                System.out.println("ProcessFaultsTest: controller JVM killed after t=" + lastSeen + " ms: the agent side told "
                        + ms + " ms later (" + gone.reason() + ")");
                assertTrue(!m.isConnected());
            } finally {
                controller.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
        }
    }

    @Test
    void sigtermEndsAHeadlessRunWritingWhatItHas(@TempDir Path dir) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Path out = dir.resolve("run");
        Path console = dir.resolve("console.txt");
        Process p = new ProcessBuilder(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                "jacabot.app.cli.JacabotCommand", "experiment", "obstacle-avoidance", "--headless", "--duration", "60m",
                "--out", out.toString(), "--link-log").directory(ROOT.toFile()).redirectErrorStream(true)
                .redirectOutput(console.toFile()).start();
        try {
            waitLong(() -> {
                try {
                    return Files.readString(console).contains("t=  10.0 s");
                } catch (IOException e) {
                    return false;
                }
            });
            long t0 = System.nanoTime();
            p.destroy(); // SIGTERM
            assertTrue(p.waitFor(30, TimeUnit.SECONDS), "SIGTERM did not end the run");
            long ms = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0);
            var written = new ArrayList<String>();
            for (String f : List.of("link-log.txt", "summary.json", "summary.txt", "event-log.txt", "trajectory.png")) {
                if (Files.exists(out.resolve(f))) {
                    written.add(f);
                }
            }
            // which files make it in the hook's 900 ms depends on the machine's load: a figure, not an assertion
            System.out.println("ProcessFaultsTest: SIGTERM ended the run in " + ms + " ms, written: " + written);
            List<String> lines = Files.readAllLines(out.resolve("link-log.txt"));
            assertTrue(lines.size() > 250, "the link log streamed up to the end: " + lines.size() + " lines");
            assertTrue(lines.stream().allMatch(l -> l.startsWith("step ")), "whole lines only");
        } finally {
            p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    /** A real-time run without the viewer (a server's) ended by SIGTERM writes what a finished run writes, the plots aside. */
    @Test
    void sigtermEndsARealTimeRunWritingItsSummaryAndConsole(@TempDir Path dir) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Path agent = Files.writeString(dir.resolve("tick.asl"), "!tick.\n+!tick <- .print(\"tick\"); .wait(300); !tick.\n");
        Path out = dir.resolve("run");
        Path said = dir.resolve("said.txt");
        Process p = new ProcessBuilder(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                "jacabot.app.cli.JacabotCommand", "experiment", "obstacle-avoidance", "--real-time", "--headless",
                "--no-inspector", "--duration", "10m", "--agent", agent.toString(), "--out", out.toString())
                .directory(ROOT.toFile()).redirectErrorStream(true).redirectOutput(said.toFile()).start();
        try {
            waitLong(() -> {
                try {
                    return Files.readString(said).contains("[robot] tick");
                } catch (IOException e) {
                    return false;
                }
            });
            p.destroy(); // SIGTERM
            // the run's shutdown hook gives it 10 s to write; a dump after 8 s shows what it waits for
            String dump = p.waitFor(8, TimeUnit.SECONDS) ? "" : threads(p);
            assertTrue(p.waitFor(30, TimeUnit.SECONDS), () -> "SIGTERM did not end the run; its threads after 8 s:\n" + dump);
            String text = Files.readString(said);
            assertTrue(text.contains("Stopped by a signal at t="), () -> text + "\nits threads 8 s after the signal:\n" + dump);
            for (String f : List.of("summary.json", "summary.txt", "event-log.txt", "trajectory.png", "steps.jsonl.gz",
                    "console.txt")) {
                assertTrue(Files.exists(out.resolve(f)), f + " written: " + text);
            }
            assertTrue(Files.readString(out.resolve("console.txt")).contains("[robot] tick"));
            assertTrue(text.contains("Plots: not drawn after a signal; draw them with: jacabot plot " + out), text);
        } finally {
            p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    /** {@return the thread dump of a process still running (jstack), to tell why it did not end} */
    private static String threads(Process p) {
        try {
            Path jstack = Path.of(System.getProperty("java.home"), "bin", "jstack");
            Process dump = new ProcessBuilder(jstack.toString(), Long.toString(p.pid())).redirectErrorStream(true).start();
            String text = new String(dump.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            dump.waitFor(30, TimeUnit.SECONDS);
            return text;
        } catch (IOException | InterruptedException e) {
            return "(no thread dump: " + e + ")";
        }
    }
}
