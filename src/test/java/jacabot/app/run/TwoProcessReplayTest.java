package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.ControllerConfig;
import jacabot.robot.Experiment;
import jacabot.robot.RobotController;
import jacabot.robot.link.LinkSecret;
import jacabot.sim.SimWorld;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Reliability (docs/reliability.md): the two-process lockstep set-up is the same run as the in-process one. The agent side
 * waits for a controller of its own world file ({@link LockstepRun#remoteController}), which the
 * test runs on its own {@code SimWorld}, as {@code jacabot controller --lockstep} does; both event
 * logs, the controller's and the agent side's, must equal the in-process run's line for line.
 */
class TwoProcessReplayTest {
    private static final double SECONDS = 20;

    private static AgentSource agent(Experiment e) {
        return AgentSource.packaged(e);
    }

    private static SimWorld world(Experiment e) throws Exception {
        return SimWorld.load(Path.of(System.getProperty("jacabot.rootDir", "."), e.worldFile()));
    }

    @ParameterizedTest
    @EnumSource(value = Experiment.class, names = {"OBSTACLE_AVOIDANCE", "NAVIGATION"})
    void theTwoProcessLockstepRunIsTheInProcessRun(Experiment e) throws Exception {
        runInOneProcessAndTwo(e, false);
    }

    /** The pipelined lockstep is the controller's: the agent side answers each step as in lockstep. */
    @ParameterizedTest
    @EnumSource(value = Experiment.class, names = {"OBSTACLE_AVOIDANCE"})
    void theTwoProcessPipelinedRunIsTheInProcessOne(Experiment e) throws Exception {
        runInOneProcessAndTwo(e, true);
    }

    private static void runInOneProcessAndTwo(Experiment e, boolean pipelined) throws Exception {
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        SimWorld w = world(e);
        var one = new LockstepRun(w, null, e, agent(e), w.seed(), quiet).pipeline(pipelined).runFor(SECONDS);

        LinkSecret secret = LinkSecret.random();
        LinkSecret.useInThisProcess(secret); // the agent side's "user secret"; the controller is given it
        SimWorld agentSide = world(e);
        var two = new LockstepRun(agentSide, null, e, agent(e), agentSide.seed(), quiet)
                .remoteController(true); // port 0: a free one
        LockstepCoordinator.Result[] result = new LockstepCoordinator.Result[1];
        Throwable[] failed = new Throwable[1];
        Thread agents = new Thread(() -> {
            try {
                result[0] = two.runFor(SECONDS);
            } catch (Throwable t) {
                failed[0] = t;
            }
        }, "agent-side");
        agents.start();
        long listening = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (two.listeningPort() == 0 && failed[0] == null && System.nanoTime() < listening) {
            Thread.sleep(10);
        }
        assertTrue(failed[0] == null, () -> "the agent side failed: " + failed[0]);
        int port = two.listeningPort();
        List<String> controllerLog = new CopyOnWriteArrayList<>();
        var cc = ControllerConfig.defaults().withAddress("127.0.0.1", port).withSecret(secret).withLockstep(true)
                .withBackoff(20, 200).withLog(line -> { }).withEventLog(controllerLog::add);
        try (var controller = new RobotController(world(e), cc).pipelined(pipelined)) {
            controller.start();
            Thread simulation = new Thread(() -> controller.runner().runFor(SECONDS), "controller-side");
            simulation.setDaemon(true);
            simulation.start();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (simulation.isAlive() && System.nanoTime() < end && (agents.isAlive() || result[0] != null)) {
                simulation.join(100);
            }
            assertTrue(failed[0] == null, () -> "the agent side failed: " + failed[0] + "; controller: " + controller.lastProblem());
            assertTrue(!simulation.isAlive(), () -> "the controller did not finish; its last problem: " + controller.lastProblem()
                    + "; the agent side's link log: " + (result[0] != null ? result[0].linkLog() : "(running)"));
        } finally {
            LinkSecret.resetUserDefault();
        }
        agents.join(TimeUnit.SECONDS.toMillis(120));
        assertTrue(result[0] != null, "the agent side did not end");
        assertEquals(agentSide.timeMs(), 0, "the agent side's world is not stepped");
        assertEquals(one.steps(), result[0].steps());
        assertEquals(String.join("\n", one.controllerLog()), String.join("\n", controllerLog), "controller's event log");
        assertEquals(String.join("\n", one.agentLog()), String.join("\n", result[0].agentLog()), "agent side's event log");
        assertTrue(controllerLog.stream().anyMatch(l -> l.contains(" apply ")), "the agent drove");
        System.out.printf("TwoProcessReplayTest %s%s: %d steps, %d + %d log lines identical%n", e.id(), pipelined ? " pipelined" : "", one.steps(),
                controllerLog.size(), one.agentLog().size());
    }
}
