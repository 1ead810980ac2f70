package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.MindHistory;
import jacabot.app.inspector.MindState;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The step log read on demand: a 10-minute run's any instant, rebuilt from the key step of its
 * gzip member, is the instant the log holds; and the log is still one gzip stream for any reader.
 */
class StepArchiveTest {
    @Test
    void anyInstantOfATenMinuteRunFromItsMember(@TempDir Path dir) throws Exception {
        SyntheticRun.write(dir, 600);
        var history = new MindHistory("robot", 10);
        StepArchive a = StepArchive.open(dir, new StepArchive.PathSink() {
            @Override
            public void point(long timeMs, double x, double z) {
                history.addToPath(timeMs, x, z);
            }

            @Override
            public void failure(MindState.Selection s) {
                history.noteFailure(s);
            }
        });
        assertEquals(10L, history.failures().get("count"), "a failed goal a minute, counted");
        assertTrue(history.failures().toString().contains("error_msg(\"no plan\")"), history.failures().toString());
        assertEquals(40, a.firstTimeMs());
        assertEquals(600_000, a.lastTimeMs());
        for (long t : new long[] {40, 41, 3_999, 4_000, 4_040, 123_440, 599_960, 600_000, 700_000}) {
            MindHistory.Frame f = a.at(t);
            long at = Math.min(600_000, t / 40 * 40);
            assertEquals(at, f.mind().timeMs(), "at " + t);
            assertEquals(SyntheticRun.x(at, 600_000), f.robot().x(), 1e-9, "x at " + t);
            assertEquals(SyntheticRun.z(at), f.robot().z(), 1e-9, "z at " + t);
            assertEquals(1, f.mind().beliefs().size(), "the mind rebuilt from its key step: " + f.mind().beliefs());
            assertEquals("second(" + at / 1000 + ")", f.mind().beliefs().get(0).literal());
            assertTrue(f.robot().objects().size() > 0, "the movable objects are placed");
        }
        var sel = a.selectionsUpTo(123_440, 60);
        assertTrue(sel.get(sel.size() - 1).event().startsWith("-!tick(24)["), sel.toString());
        // the path: one point per 100 ms of the whole run
        var path = history.pathUpTo(600_000);
        assertTrue(path.size() >= 4_900, "path points: " + path.size());
        assertEquals(-0.4, path.get(0)[0], 0.01);
        // the chain of members is still one gzip stream: the replay reads it whole
        Replay r = Replay.open(dir);
        assertEquals(15_000, r.frames().size());
        assertEquals("second(300)", r.frames().get(7_499).mind().beliefs().get(0).literal());
        assertNotNull(r.world(7_499));
    }
}
