package jacabot.app.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Several lockstep runs share one JVM safely: a run's event log and figures are the same alone and
 * among others on a pool of threads (no shared statics, a link per run, seeds per run).
 */
class SweepConcurrencyTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    static final double SECONDS = 65; // past the world's three scripted events (20, 40, 60 s)

    @Test
    void aRunIsTheSameAloneAndInASweep() throws Exception {
        Path file = ROOT.resolve(Experiment.OBSTACLE_AVOIDANCE.worldFile());
        WorldSpec spec = WorldFileReader.read(file);
        SweepJob agent = new SweepJob(Experiment.OBSTACLE_AVOIDANCE, SweepJob.AGENT, "obstacle-avoidance", file, spec, null, 2);
        SweepJob baseline = new SweepJob(Experiment.OBSTACLE_AVOIDANCE, SweepJob.BASELINE, "obstacle-avoidance", file, spec, null, 2);
        SweepJob other = new SweepJob(Experiment.OBSTACLE_AVOIDANCE, SweepJob.AGENT, "obstacle-avoidance", file, spec, null, 5);

        SweepRun.Result alone = SweepRun.run(agent, SECONDS, 600);
        assertEquals(RunOutcome.OK, alone.outcome().status(), alone.outcome().reason());
        assertTrue(alone.eventLog().contains("world: "), "the log holds the scripted events: " + alone.eventLog());

        List<SweepJob> jobs = List.of(other, agent, baseline, agent);
        var results = new ArrayList<SweepRun.Result>();
        Sweep.Outcomes outcomes = new Sweep(3, SECONDS, 600).onResult(results::add).run(jobs);
        assertEquals(4, outcomes.runs().size());
        int same = 0;
        for (SweepRun.Result r : results) {
            RunOutcome o = r.outcome();
            if (o.controller().equals(SweepJob.AGENT) && o.seed() == 2) {
                assertEquals(alone.eventLog(), r.eventLog());
                assertEquals(alone.outcome().figures(), o.figures());
                same++;
            }
        }
        assertEquals(2, same, "both copies of the run finished");
        assertTrue(outcomes.simulatedMinutesPerSecond() > 0);
        // the CPU figure (HotSpot tells it): four runs of real work cost CPU time, and less than all cores' wall time
        assertTrue(outcomes.cpuSeconds() > 0.1 && outcomes.cpuSeconds() < outcomes.wallSeconds()
                * Runtime.getRuntime().availableProcessors() + 1, outcomes.cpuSeconds() + " s of CPU in " + outcomes.wallSeconds());
        assertEquals(outcomes.runs().stream().mapToDouble(RunOutcome::simulated).sum() / 60 / outcomes.cpuSeconds(),
                outcomes.simulatedMinutesPerCpuSecond(), 1e-9);
    }
}
