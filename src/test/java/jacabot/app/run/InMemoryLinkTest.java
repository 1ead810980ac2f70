package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.sweep.SweepJob;
import jacabot.robot.ControllerConfig;
import jacabot.robot.Experiment;
import jacabot.robot.RobotController;
import jacabot.robot.link.MemoryLink;
import jacabot.robot.run.RunRecorder;
import jacabot.sim.SimWorld;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Sweeps run lockstep over an in-process link ({@link LockstepRun#inMemory}) only because
 * it is the same run as over the socket: the controller's and the agent side's event logs, and the
 * run's summary and recorded event log, equal the socket run's to the byte.
 */
class InMemoryLinkTest {
    private static final double SECONDS = 40;

    private static AgentSource agent(Experiment e) {
        return AgentSource.packaged(e);
    }

    private static SimWorld world(Experiment e) throws Exception {
        return SimWorld.load(Path.of(System.getProperty("jacabot.rootDir", "."), e.worldFile()));
    }

    /** What a run leaves that two runs must agree on, and its link log (which tells the two links apart). */
    private record Run(String eventLog, long steps, String summary, String recorded, List<String> linkLog) {
    }

    private static Run run(Experiment e, boolean inMemory) throws Exception {
        SimWorld w = world(e);
        RunRecorder recorder = RunRecorder.attach(w, e.robot());
        var result = new LockstepRun(w, null, e, agent(e), w.seed(),
                new PrintStream(OutputStream.nullOutputStream())).inMemory(inMemory).runFor(SECONDS);
        var summary = recorder.summary(SweepJob.AGENT);
        return new Run(result.eventLog(), result.steps(), summary.toJson(), summary.eventLog(), result.linkLog());
    }

    @ParameterizedTest
    @EnumSource(value = Experiment.class, names = {"OBSTACLE_AVOIDANCE", "SUSPEND_RESUME"})
    void theInMemoryRunIsTheSocketRunToTheByte(Experiment e) throws Exception {
        Run socket = run(e, false);
        Run memory = run(e, true);
        assertTrue(socket.linkLog().stream().anyMatch(l -> l.startsWith("connected to the middleware at 127.0.0.1:")),
                () -> "the socket run used a socket: " + socket.linkLog());
        assertTrue(memory.linkLog().contains("connected to the middleware in this process"),
                () -> "the in-memory run used no socket: " + memory.linkLog());
        assertEquals(Math.round(SECONDS * 1000) / world(e).controlStep(), memory.steps(), "every control step answered");
        assertEquals(socket.steps(), memory.steps());
        assertEquals(socket.eventLog(), memory.eventLog(), "the controller's and the agent side's event logs");
        assertEquals(socket.summary(), memory.summary(), "the run's summary");
        assertEquals(socket.recorded(), memory.recorded(), "the recorder's event log");
        assertTrue(memory.eventLog().contains(" apply "), "the agent drove the robot");
        System.out.printf("InMemoryLinkTest %s: %d steps, %d characters of event log identical%n", e.id(), memory.steps(),
                memory.eventLog().length());
    }

    @Test
    void aRunOverTheInProcessLinkStopsFromAnotherThread() throws Exception {
        Experiment e = Experiment.NAVIGATION;
        SimWorld w = world(e);
        var run = new LockstepRun(w, null, e, agent(e), w.seed(),
                new PrintStream(OutputStream.nullOutputStream())).inMemory(true);
        var fiveSeconds = new CountDownLatch(1);
        run.onStep(d -> {
            if (d.simTimeMs() >= 5000) {
                fiveSeconds.countDown();
            }
        });
        LockstepCoordinator.Result[] result = new LockstepCoordinator.Result[1];
        Throwable[] failed = new Throwable[1];
        Thread t = new Thread(() -> {
            try {
                result[0] = run.runFor(3600);
            } catch (Throwable x) {
                failed[0] = x;
            }
        }, "in-memory-run");
        t.start();
        assertTrue(fiveSeconds.await(60, TimeUnit.SECONDS), () -> "5 simulated seconds within 60 s; failure: " + failed[0]);
        run.stop(); // the agent answers on the simulation thread: stop must not wait for it for ever
        t.join(TimeUnit.SECONDS.toMillis(30));
        assertTrue(!t.isAlive(), "the run ended after stop()");
        assertTrue(failed[0] == null, () -> "the run failed: " + failed[0]);
        assertTrue(result[0].steps() >= 5000 / w.controlStep() && result[0].steps() < 3600_000 / w.controlStep(),
                "cut short after 5 s: " + result[0].steps() + " steps");
    }

    @Test
    void theInProcessLinkServesLockstepOnly() throws Exception {
        SimWorld w = world(Experiment.NAVIGATION);
        var e = assertThrows(IllegalArgumentException.class,
                () -> new RobotController(w, ControllerConfig.defaults().withLockstep(false), new MemoryLink(w)));
        assertTrue(e.getMessage().contains("lockstep"), e.getMessage());
    }
}
