package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindState;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The inspector and the step log only read the run: a lockstep run is the same with them as
 * without; and the step log read back gives the agent's mind as it was.
 */
class RunTapTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    static final Experiment NAVIGATION = Experiment.parse("navigation").orElseThrow();

    private static LockstepRun run() throws Exception {
        var spec = WorldFileReader.read(ROOT.resolve(NAVIGATION.worldFile()));
        return new LockstepRun(SimWorld.of(spec), null, NAVIGATION, AgentSource.packaged(NAVIGATION), 4,
                new PrintStream(OutputStream.nullOutputStream()));
    }

    @Test
    void sameRunWithOrWithoutInspectorAndLog(@TempDir Path dir) throws Exception {
        var plain = run();
        String without = plain.runFor(15).eventLog();

        var watched = run();
        String with;
        try (Inspector inspector = Inspector.startOnFreePort();
                RunTap tap = RunTap.attach(watched, inspector, dir, NAVIGATION, "navigation.asl")) {
            with = watched.runFor(15).eventLog();
            var h = inspector.add("robot");
            assertNotNull(h.latest());
            assertFalse(h.selections().isEmpty(), "plan selections recorded");
            assertTrue(h.timeline().size() > 10, "frames kept: " + h.timeline().size());
        }
        assertEquals(without, with, "the inspector and the step log change nothing");
        assertEquals(plain.cycles(), watched.cycles());

        // read back: one frame per control step, the mind rebuilt from its changes
        Replay replay = Replay.open(dir);
        assertEquals("navigation", replay.header().experiment());
        var last = replay.frames().get(replay.frames().size() - 1);
        assertTrue(last.timeMs() >= 14_000, "last frame at " + last.timeMs());
        assertTrue(last.mind().beliefs().stream().anyMatch(b -> b.literal().startsWith("maxSpeed(")), "initial belief kept");
        assertTrue(last.mind().beliefs().stream().anyMatch(MindState.Belief::isPercept), "percepts recorded");
        long selections = replay.frames().stream().mapToLong(f -> f.mind().selections().size()).sum();
        assertTrue(selections > 5, "selections: " + selections);
        assertEquals(watched.cycles(), last.mind().cycle());
        // the robot moved, and the replayed pose is the recorded one
        var first = replay.frames().get(0).body();
        assertTrue(Math.hypot(last.body().x() - first.x(), last.body().z() - first.z()) > 0.05, "the robot moved");
        assertNotNull(replay.world(replay.frames().size() - 1).robots().get(0).pose());
    }
}
