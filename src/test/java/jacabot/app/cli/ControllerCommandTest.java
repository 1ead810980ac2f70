package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.experiments.link.LinkConfig;
import jacabot.experiments.link.LinkEvent;
import jacabot.experiments.link.MiddlewareLink;
import jacabot.robot.link.LinkSecret;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ControllerCommandTest {
    private static final String NAVIGATION =
            Path.of(System.getProperty("jacabot.rootDir", "."), "worlds", "navigation.json").toString();

    private static String[] run(String... args) {
        return CliRun.run(args);
    }

    private static void assertUserError(String[] result, String message) {
        assertEquals("2", result[0], result[2]);
        assertTrue(result[2].contains(message), result[2]);
        assertFalse(result[2].contains("\tat "), "no stack trace: " + result[2]);
    }

    @Test
    void anInvalidWorldFileIsReportedWithItsJsonPathAndExitCode2(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.json");
        Files.writeString(bad, "{ \"robots\": [ { \"name\": \"k\", \"model\": \"tank\" } ] }");
        var result = run("controller", "--world", bad.toString());
        assertUserError(result, bad + ": $.robots[0].model");
        // said once, as the other commands say it: not as a world that "cannot run", its name twice
        assertTrue(result[2].startsWith("error: " + bad + ": $.robots[0].model"), result[2]);
        assertUserError(run("controller", "--world", dir.resolve("missing.json").toString()), "cannot read the world file");
    }

    @Test
    void badOptionsAreUserErrors() {
        assertUserError(run("controller", "--world", NAVIGATION, "--robot", "r2d2"), "no robot named 'r2d2'");
        assertUserError(run("controller", "--world", NAVIGATION, "--speed", "0"), "speed factor must be a positive number");
        assertUserError(run("controller", "--world", NAVIGATION, "--port", "70000"), "port must be in 0..65535");
        assertUserError(run("controller"), "Missing required option: '--world=FILE'");
        assertUserError(run("controller", "--world", NAVIGATION, "--pipeline"), "--pipeline goes with --lockstep");
    }

    @Test
    void aTeamWorldsControllerRunsInLockstepAndWritesPerRobot(@TempDir Path dir) {
        String team = Path.of(System.getProperty("jacabot.rootDir", "."), "worlds", "team-delivery.json").toString();
        String secret = dir.resolve("secret").toString();
        assertUserError(run("controller", "--world", team, "--secret-file", secret), "runs in lockstep only: add --lockstep");
        String[] nine = run("controller", "--world", team, "--lockstep", "--robots", "9", "--secret-file", secret);
        assertUserError(nine, "--robots must be in 1..4");
        assertEquals("error: --robots must be in 1..4 (the robots of " + team + "), got 9", nine[2].strip());
        String[] both = run("controller", "--world", team, "--robots", "2", "--robot", "khepera1", "--secret-file", secret);
        assertEquals("error: --robots N makes a team, --robot NAME runs one robot: choose one", both[2].strip());
        assertUserError(run("controller", "--world", team, "--lockstep", "--event-log", dir.resolve("e").toString(),
                "--secret-file", secret), "use --out DIR --link-log");
        assertUserError(run("controller", "--world", NAVIGATION, "--out", dir.toString(), "--secret-file", secret), "--out is for a team");
        assertUserError(run("controller", "--world", team, "--lockstep", "--pipeline", "--secret-file", secret),
                "--pipeline: a team's controller runs in plain lockstep only");
    }

    @Test
    void theControllerConnectsToARunningMiddleware(@TempDir Path dir) throws Exception {
        Path secretFile = dir.resolve("secret");
        var secret = LinkSecret.loadOrCreate(secretFile); // made 0600, as the launchers do
        assertFalse(Files.getPosixFilePermissions(secretFile).contains(PosixFilePermission.OTHERS_READ));
        try (var link = MiddlewareLink.open(LinkConfig.defaults().withPort(0).withLog(line -> { }).withSecret(secret))) {
            var result = run("controller", "--world", NAVIGATION, "--port", String.valueOf(link.port()), "--speed", "10",
                    "--seconds", "5", "--secret-file", secretFile.toString());
            assertEquals("0", result[0], result[2]);
            assertTrue(result[1].startsWith("controller: robot 'khepera' (khepera) of world 'navigation', real time x10.0; "
                    + "middleware at 127.0.0.1:" + link.port()), result[1]);
            assertTrue(result[1].contains("stopped at t=5.00 s after 125 steps"), result[1]);
            var first = link.poll(5, TimeUnit.SECONDS);
            assertTrue(first instanceof LinkEvent.Connected, String.valueOf(first));
        }
    }
}
