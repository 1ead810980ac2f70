package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.ControllerConfig;
import jacabot.robot.Experiment;
import jacabot.robot.RobotController;
import jacabot.robot.link.LinkSecret;
import jacabot.sim.SimWorld;
import java.io.InputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Issue 16: the two-process lockstep set-up is the same run as the in-process one. The agent side
 * waits for a controller of its own world file ({@link LockstepRun#remoteController}), which the
 * test runs on its own {@code SimWorld}, as {@code jacabot controller --lockstep} does; both event
 * logs, the controller's and the agent side's, must equal the in-process run's line for line.
 */
class TwoProcessReplayTest {
    private static final double SECONDS = 20;

    private static String agent(Experiment e) throws Exception {
        try (InputStream in = TwoProcessReplayTest.class.getResourceAsStream(e.agentResource())) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private static SimWorld world(Experiment e) throws Exception {
        return SimWorld.load(Path.of(System.getProperty("jacabot.rootDir", "."), e.worldFile()));
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    @ParameterizedTest
    @EnumSource(value = Experiment.class, names = {"OBSTACLE_AVOIDANCE", "NAVIGATION"})
    void theTwoProcessLockstepRunIsTheInProcessRun(Experiment e) throws Exception {
        PrintStream quiet = new PrintStream(java.io.OutputStream.nullOutputStream());
        SimWorld w = world(e);
        var one = new LockstepRun(w, null, e, agent(e), e.id() + ".asl", w.seed(), quiet).runFor(SECONDS);

        LinkSecret secret = LinkSecret.random();
        LinkSecret.useInThisProcess(secret); // the agent side's "user secret"; the controller is given it
        int port = freePort();
        SimWorld agentSide = world(e);
        var two = new LockstepRun(agentSide, null, e, agent(e), e.id() + ".asl", agentSide.seed(), quiet)
                .port(port).remoteController(true);
        LockstepCoordinator.Result[] result = new LockstepCoordinator.Result[1];
        Thread agents = new Thread(() -> {
            try {
                result[0] = two.runFor(SECONDS);
            } catch (Exception failed) {
                throw new IllegalStateException(failed);
            }
        }, "agent-side");
        agents.start();
        List<String> controllerLog = new CopyOnWriteArrayList<>();
        var cc = ControllerConfig.defaults().withAddress("127.0.0.1", port).withSecret(secret).withLockstep(true)
                .withBackoff(20, 200).withLog(line -> { }).withEventLog(controllerLog::add);
        try (var controller = new RobotController(world(e), cc)) {
            controller.start();
            controller.runner().runFor(SECONDS);
        }
        agents.join(TimeUnit.SECONDS.toMillis(120));
        LinkSecret.resetUserDefault();
        assertTrue(result[0] != null, "the agent side did not end");
        assertEquals(agentSide.timeMs(), 0, "the agent side's world is not stepped");
        assertEquals(one.steps(), result[0].steps());
        assertEquals(String.join("\n", one.controllerLog()), String.join("\n", controllerLog), "controller's event log");
        assertEquals(String.join("\n", one.agentLog()), String.join("\n", result[0].agentLog()), "agent side's event log");
        assertTrue(controllerLog.stream().anyMatch(l -> l.contains(" apply ")), "the agent drove");
        System.out.printf("TwoProcessReplayTest %s: %d steps, %d + %d log lines identical%n", e.id(), one.steps(),
                controllerLog.size(), one.agentLog().size());
    }
}
