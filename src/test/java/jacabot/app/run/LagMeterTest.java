package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.semantics.Event;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Trigger;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The lag of a real-time run, on a wall clock of the test's own: the world behind real time, the agent behind the world. */
class LagMeterTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    private final long[] wall = {0};
    private final List<String> heard = new ArrayList<>();

    private LagMeter meter(SimRunner runner) {
        return new LagMeter(runner, () -> wall[0]).addListener(new LagMeter.Listener() {
            @Override
            public void started(LagMeter.Reading r) {
                heard.add("start " + r.worldBehindMs() + " " + r.agentLateMs());
            }

            @Override
            public void ended(LagMeter.Episode e) {
                heard.add("end " + e.startMs() + "-" + e.endMs() + " " + e.worstWorldBehindMs() + " " + e.worstAgentLateMs());
            }
        });
    }

    private static SimWorld world() throws Exception {
        return SimWorld.of(WorldFileReader.read(ROOT.resolve("worlds/navigation.json")));
    }

    private static void advance(SimWorld w, long ms) {
        long end = w.timeMs() + ms;
        while (w.timeMs() < end) {
            w.step();
        }
    }

    @Test
    void aWorldSlowerThanTheSpeedAskedForLagsBehindRealTime() throws Exception {
        SimWorld w = world();
        var runner = new SimRunner(w, null);
        runner.setSpeedFactor(16);
        LagMeter m = meter(runner);
        m.sample(); // the schedule starts here
        wall[0] += 1_000_000_000L;
        advance(w, 16_000); // x16 kept: one wall second, 16 simulated seconds
        assertFalse(m.sample().lagging(), m.last().toString());
        assertEquals("", m.status());
        wall[0] += 1_000_000_000L;
        advance(w, 10_000); // 6 s short of the 16 s wanted
        var r = m.sample();
        assertTrue(r.lagging(), r.toString());
        assertEquals(6_000, r.worldBehindMs());
        assertTrue(m.status().startsWith("LAG: world 6.0 s behind real time (×16 requested"), m.status());
        assertEquals(List.of("start 6000 0"), heard);
        wall[0] += 250_000_000L;
        advance(w, 10_000); // catches up (the runner runs flat out until it is back on schedule)
        assertFalse(m.sample().lagging());
        assertEquals(List.of("start 6000 0", "end " + 26_000 + "-" + w.timeMs() + " 6000 0"), heard);
        assertEquals(1, m.episodes().size());
    }

    @Test
    void aWorldWaitingForItsControllerIsNotLaggingYet() throws Exception {
        SimWorld w = world();
        var runner = new SimRunner(w, null);
        runner.setSpeedFactor(16);
        LagMeter m = meter(runner);
        m.sample();
        wall[0] += 5_000_000_000L; // the controller connects, the agent starts: the world stays at 0
        assertFalse(m.sample().lagging());
        wall[0] += 100_000_000L;
        advance(w, 40); // the first step: the schedule starts here
        assertFalse(m.sample().lagging());
        wall[0] += 1_000_000_000L;
        advance(w, 16_000);
        assertFalse(m.sample().lagging(), m.last().toString());
        wall[0] += 1_000_000_000L;
        advance(w, 14_000);
        assertEquals(2_000, m.sample().worldBehindMs(), "from then on, behind is behind");
        assertEquals(List.of("start 2000 0"), heard);
    }

    @Test
    void pausedOrFastIsNotLagging() throws Exception {
        SimWorld w = world();
        var runner = new SimRunner(w, null);
        LagMeter m = meter(runner);
        m.sample();
        runner.setPaused(true);
        wall[0] += 10_000_000_000L; // ten seconds of pause: the world wants nothing
        assertFalse(m.sample().lagging());
        runner.setPaused(false);
        runner.setMode(SimRunner.Mode.FAST);
        wall[0] += 10_000_000_000L;
        assertFalse(m.sample().lagging());
        assertEquals(List.of(), heard);
    }

    @Test
    void anAgentAnsweringOldEventsLagsBehindTheWorld() throws Exception {
        SimWorld w = world();
        var runner = new SimRunner(w, null);
        runner.setMode(SimRunner.Mode.FAST); // only the agent's lag counts here
        LagMeter m = meter(runner);
        var trigger = new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, Literal.atom("battery_low"));
        Event first = new Event(trigger, null), same = new Event(trigger, null);
        m.posted(first);
        advance(w, 2_000);
        m.posted(same); // an equal event, two seconds younger: timed on its own
        advance(w, 1_600);
        m.planSelected(first); // answered 3.6 simulated seconds after it came
        var r = m.sample();
        assertTrue(r.lagging(), r.toString());
        assertEquals(3_600, r.agentLateMs());
        assertEquals("LAG: agent 3.6 s behind the world", m.status());
        m.planSelected(same);
        assertEquals(1_600, m.sample().agentLateMs(), "the worst answer since the last look");
        m.planSelected(new Event(trigger, null)); // never timed: no figure
        assertEquals(0, m.sample().agentLateMs(), "no agent watched is busy: idle, not behind");
        assertEquals(List.of("start 0 3600", "end " + 3_600 + "-" + w.timeMs() + " 0 3600"), heard);
    }
}
