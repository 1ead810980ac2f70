package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability (docs/reliability.md): {@code jacabot experiment NAME --remote-controller} in one JVM and {@code jacabot
 * controller --lockstep --event-log FILE} in another give the run of {@code jacabot experiment NAME
 * --headless}: the controller's event log equals the one-process run's link-log.txt byte for byte.
 */
class TwoProcessLockstepCliTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void theTwoProcessLockstepRunWritesTheSameEventLogAsTheOneProcessRun(@TempDir Path dir) throws Exception {
        String[] one = CliRun.run("experiment", "obstacle-avoidance", "--headless", "--link-log", "--duration", "15s",
                "--world", ROOT.resolve("worlds/obstacle-avoidance.json").toString(), "--out", dir.resolve("one").toString());
        assertEquals("0", one[0], one[2]);

        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        Path secret = dir.resolve("secret");
        Path agentOut = dir.resolve("agent.txt");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process agent = new ProcessBuilder(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                "jacabot.app.cli.JacabotCommand", "experiment", "obstacle-avoidance", "--remote-controller", "--duration", "15s",
                "--world", ROOT.resolve("worlds/obstacle-avoidance.json").toString(), "--out", dir.resolve("two").toString(),
                "--port", String.valueOf(port), "--secret-file", secret.toString())
                .redirectErrorStream(true).redirectOutput(agentOut.toFile()).start();
        try {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (!Files.readString(agentOut).contains("Waiting for") && System.nanoTime() < end) {
                assertTrue(agent.isAlive(), Files.readString(agentOut));
                Thread.sleep(50);
            }
            Path log = dir.resolve("controller-log.txt");
            String[] c = CliRun.run("controller", "--world", ROOT.resolve("worlds/obstacle-avoidance.json").toString(),
                    "--lockstep", "--seconds", "15", "--port", String.valueOf(port), "--secret-file", secret.toString(),
                    "--event-log", log.toString());
            assertEquals("0", c[0], c[2]);
            assertTrue(agent.waitFor(60, TimeUnit.SECONDS), "the agent side did not end: " + Files.readString(agentOut));
            String said = Files.readString(agentOut, StandardCharsets.UTF_8);
            assertEquals(0, agent.exitValue(), said);
            assertTrue(said.contains("375 steps (15.0 s simulated) with the remote controller"), said);
            String expected = Files.readString(dir.resolve("one/link-log.txt"));
            String actual = Files.readString(log);
            assertTrue(actual.contains(" apply "), "the agent drove");
            assertEquals(expected, actual, "the controller's event log is the one-process run's link log");
            // the agent side's console by simulated time: the one-process run's, without the world's event log
            assertTrue(said.contains("console.txt"), said);
            var events = Files.readAllLines(dir.resolve("one/event-log.txt"));
            var oneConsole = Files.readAllLines(dir.resolve("one/console.txt")).stream().filter(l -> !events.contains(l)).toList();
            assertTrue(!oneConsole.isEmpty(), "the agent's console has lines");
            assertEquals(oneConsole, Files.readAllLines(dir.resolve("two/console.txt")));
        } finally {
            agent.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }
}
