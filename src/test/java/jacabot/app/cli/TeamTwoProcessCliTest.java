package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A team in two processes from the command line (thesis Chapter 6): {@code jacabot experiment
 * team-delivery --remote-controller} in one JVM, {@code jacabot controller --lockstep --world FILE
 * --robots 2 --out DIR --link-log} in another, give every robot the ground-truth event log and the
 * link log of the one-process {@code jacabot experiment team-delivery --link-log}, byte for byte.
 * Tagged long (three JVMs' runs, about a minute on a loaded machine); {@code jacabot.app.run.TeamTwoProcessTest}
 * checks the same in one JVM within seconds.
 */
class TeamTwoProcessCliTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    private static final String WORLD = ROOT.resolve("worlds/team-delivery.json").toString();

    /** {@return a port free with the next one} */
    private static int twoFreePorts() throws IOException {
        for (int i = 0; i < 20; i++) {
            try (ServerSocket a = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
                 ServerSocket b = new ServerSocket(a.getLocalPort() + 1, 1, InetAddress.getLoopbackAddress())) {
                return a.getLocalPort();
            } catch (IOException taken) {
                // the next one was taken: try another
            }
        }
        throw new IOException("no two free ports in a row");
    }

    @Test
    @Tag("long")
    void theTeamsControllersInAProcessOfTheirOwnWriteTheOneProcessRunsLogs(@TempDir Path dir) throws Exception {
        String[] one = CliRun.run("experiment", "team-delivery", "--robots", "2", "--duration", "6s", "--link-log",
                "--world", WORLD, "--out", dir.resolve("one").toString());
        assertEquals("0", one[0], one[2]);

        int port = twoFreePorts();
        Path secret = dir.resolve("secret");
        Path agentOut = dir.resolve("agents.txt");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process agents = new ProcessBuilder(java, "-Xmx384m", "-cp", System.getProperty("java.class.path"),
                "jacabot.app.cli.JacabotCommand", "experiment", "team-delivery", "--robots", "2", "--remote-controller",
                "--duration", "6s", "--world", WORLD, "--port", String.valueOf(port), "--secret-file", secret.toString())
                .redirectErrorStream(true).redirectOutput(agentOut.toFile()).start();
        try {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (!Files.readString(agentOut).contains("Waiting for") && System.nanoTime() < end) {
                assertTrue(agents.isAlive(), Files.readString(agentOut));
                Thread.sleep(50);
            }
            String[] c = CliRun.run("controller", "--world", WORLD, "--lockstep", "--robots", "2", "--seconds", "6",
                    "--port", String.valueOf(port), "--secret-file", secret.toString(), "--out", dir.resolve("two").toString(), "--link-log");
            assertEquals("0", c[0], c[2]);
            assertTrue(c[1].contains("a team of 2 robots (khepera1, khepera2)"), c[1]);
            assertTrue(agents.waitFor(60, TimeUnit.SECONDS), "the agents' side did not end: " + Files.readString(agentOut));
            String said = Files.readString(agentOut, StandardCharsets.UTF_8);
            assertEquals(0, agents.exitValue(), said);
            assertTrue(said.contains("150 steps (6.0 s simulated) with the remote controllers, 2 robots"), said);
            for (String robot : List.of("khepera1", "khepera2")) {
                String links = Files.readString(dir.resolve("two").resolve(robot).resolve("link-log.txt"));
                assertTrue(links.contains(" apply "), robot + "'s agent drove");
                assertEquals(Files.readString(dir.resolve("one").resolve(robot).resolve("link-log.txt")), links, robot + "'s link log");
                assertEquals(Files.readString(dir.resolve("one").resolve(robot).resolve("event-log.txt")),
                        Files.readString(dir.resolve("two").resolve(robot).resolve("event-log.txt")), robot + "'s event log");
            }
        } finally {
            agents.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }
}
