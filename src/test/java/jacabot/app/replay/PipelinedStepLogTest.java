package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.Debugger;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.app.run.TimingJitter;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The step log reads the world on the simulation thread at each step and the agent's mind after
 * the step's answer: the same log as a capture made before the answer (as a debugger has it), and
 * in a pipelined lockstep, where the world is a step ahead by then, still a function of world,
 * agent and seed, whichever side is slowed at random steps.
 */
class PipelinedStepLogTest {
    private static final Experiment E = Experiment.SUSPEND_RESUME;
    private static final double SECONDS = 20;

    private static String stepLog(Path dir, boolean pipeline, boolean debugger, TimingJitter jitter) throws Exception {
        SimWorld w = SimWorld.load(RunTapTest.ROOT.resolve(E.worldFile()));
        var run = new LockstepRun(w, null, E, AgentSource.packaged(E), w.seed(), new PrintStream(OutputStream.nullOutputStream()))
                .pipeline(pipeline);
        jitter.apply(w, run);
        try (RunTap tap = RunTap.attach(run, null, dir, E, "suspend-resume.asl")) {
            if (debugger) {
                tap.debugger(new Debugger()); // never halts: the mind captured before the answer
            }
            run.runFor(SECONDS);
        }
        run.close();
        try (var in = new GZIPInputStream(Files.newInputStream(dir.resolve(StepLog.FILE)))) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    @Test
    void theMindCapturedAfterTheAnswerIsTheMindBeforeIt(@TempDir Path dir) throws Exception {
        String before = stepLog(dir.resolve("a"), false, true, TimingJitter.NONE);
        String after = stepLog(dir.resolve("b"), false, false, TimingJitter.AGENT);
        assertEquals(before, after);
        assertEquals(Math.round(SECONDS * 1000 / 40), before.lines().count() - 1, "a line per step after the header");
    }

    @Test
    void aPipelinedStepLogIsTheSameWhateverTheTiming(@TempDir Path dir) throws Exception {
        String agentSlow = stepLog(dir.resolve("a"), true, false, TimingJitter.AGENT);
        String worldSlow = stepLog(dir.resolve("w"), true, false, TimingJitter.WORLD);
        String withDebugger = stepLog(dir.resolve("d"), true, true, TimingJitter.WORLD);
        assertEquals(agentSlow, worldSlow);
        assertEquals(agentSlow, withDebugger);
        String plain = stepLog(dir.resolve("p"), false, false, TimingJitter.NONE);
        assertNotEquals(plain, agentSlow, "a command takes effect a step later");
        assertTrue(agentSlow.lines().count() > 400);
    }
}
