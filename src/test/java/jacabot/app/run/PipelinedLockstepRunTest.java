package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.sweep.SweepJob;
import jacabot.robot.Experiment;
import jacabot.robot.run.RunRecorder;
import jacabot.sim.SimWorld;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A pipelined lockstep ({@link LockstepRun#pipeline}) is still a function of world, agent and seed:
 * whichever of the world and the agent is slower at each step (each slowed here at random steps),
 * over the socket or in memory, the event logs are the same to the byte; and the agent's commands
 * take effect exactly one control step later than in the plain lockstep.
 */
class PipelinedLockstepRunTest {
    private static final double SECONDS = 30;
    private static final Pattern APPLY = Pattern.compile("(?m)^step (\\d+) apply ");
    private static final Pattern ANSWER = Pattern.compile("(?m)^step (\\d+) t=\\d+ [^\\n]* -> \\[[^\\]]");

    private record Run(String eventLog, long steps, String summary, String recorded, String failure) {
    }

    /** Stops the system one simulated second in: a failed agent, whose run ends there. */
    private static final AgentSource STOPS = AgentSource.text("stops.asl", "!start.\n+!start <- .wait(1000); .stopMAS.\n");

    private static SimWorld world(Experiment e) throws Exception {
        return SimWorld.load(Path.of(System.getProperty("jacabot.rootDir", "."), e.worldFile()));
    }

    private static Run run(Experiment e, boolean pipeline, boolean inMemory, TimingJitter jitter) throws Exception {
        return run(e, AgentSource.packaged(e), pipeline, inMemory, jitter);
    }

    private static Run run(Experiment e, AgentSource agent, boolean pipeline, boolean inMemory, TimingJitter jitter) throws Exception {
        SimWorld w = world(e);
        RunRecorder recorder = RunRecorder.attach(w, e.robot());
        var run = new LockstepRun(w, null, e, agent, w.seed(),
                new PrintStream(OutputStream.nullOutputStream())).inMemory(inMemory).pipeline(pipeline);
        jitter.apply(w, run);
        var result = run.runFor(SECONDS);
        run.close();
        var summary = recorder.summary(SweepJob.AGENT);
        return new Run(result.eventLog(), result.steps(), summary.toJson(), summary.eventLog(),
                run.agentFailure().orElse(""));
    }

    @ParameterizedTest
    @EnumSource(value = Experiment.class, names = {"OBSTACLE_AVOIDANCE", "SUSPEND_RESUME"})
    void thePipelinedRunIsTheSameWhateverTheTimingAndTheLink(Experiment e) throws Exception {
        Run agentSlow = run(e, true, false, TimingJitter.AGENT);
        Run worldSlow = run(e, true, false, TimingJitter.WORLD);
        Run memory = run(e, true, true, TimingJitter.NONE);
        assertEquals(Math.round(SECONDS * 1000) / world(e).controlStep(), memory.steps(), "every control step answered");
        for (Run other : List.of(worldSlow, memory)) {
            assertEquals(agentSlow.steps(), other.steps());
            assertEquals(agentSlow.eventLog(), other.eventLog(), "the controller's and the agent side's event logs");
            assertEquals(agentSlow.summary(), other.summary(), "the run's summary");
            assertEquals(agentSlow.recorded(), other.recorded(), "the recorder's event log");
        }
        assertTrue(memory.eventLog().contains(" apply "), "the agent drove the robot");
    }

    @ParameterizedTest
    @EnumSource(value = Experiment.class, names = {"OBSTACLE_AVOIDANCE", "SUSPEND_RESUME"})
    void theAgentsFirstCommandsTakeEffectOneControlStepLater(Experiment e) throws Exception {
        Run lockstep = run(e, false, true, TimingJitter.NONE);
        Run pipelined = run(e, true, true, TimingJitter.NONE);
        long answered = first(ANSWER, lockstep.eventLog());
        assertEquals(answered, first(ANSWER, pipelined.eventLog()), "the same readings until a command takes effect");
        assertEquals(answered, first(APPLY, lockstep.eventLog()), "lockstep: applied at the step it answers");
        assertEquals(answered + 1, first(APPLY, pipelined.eventLog()), "pipelined: applied at the next step");
        assertNotEquals(lockstep.eventLog(), pipelined.eventLog());
    }

    @Test
    void aFailedAgentEndsThePipelinedRunAtTheSameStepWhateverTheTiming() throws Exception {
        Experiment e = Experiment.OBSTACLE_AVOIDANCE;
        Run lockstep = run(e, STOPS, false, true, TimingJitter.NONE);
        for (int i = 0; i < 3; i++) { // the end is decided where the answer is taken, not where the agent fails
            Run agentSlow = run(e, STOPS, true, false, TimingJitter.AGENT);
            Run worldSlow = run(e, STOPS, true, false, TimingJitter.WORLD);
            Run memory = run(e, STOPS, true, true, TimingJitter.NONE);
            assertTrue(memory.failure().contains(".stopMAS"), memory.failure());
            assertEquals(lockstep.steps() + 1, memory.steps(), "one step after the plain lockstep's end");
            for (Run other : List.of(agentSlow, worldSlow)) {
                assertEquals(memory.steps(), other.steps());
                assertEquals(memory.eventLog(), other.eventLog());
            }
        }
    }

    private static long first(Pattern p, String log) {
        Matcher m = p.matcher(log);
        assertTrue(m.find(), () -> p + " in the event log");
        return Long.parseLong(m.group(1));
    }
}
