package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.Clock;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** An internal operation looping on await_time, in real and in simulated time. */
class ClockTest {
    @Test
    void wallClockTicksUntilStopped() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ws.createArtifact("clock", Clock.class, 5);
            ok(ws, agent, "focus", "clock");
            ok(ws, agent, "start");
            OpOutcome.Failure again = Calls.failure(ws, agent, OpTarget.any(), "start");
            assertEquals(new OpOutcome.Failure("already working", null, List.of()), again);
            obs.skipUntil("clock !tick[3]");
            ok(ws, agent, "stop");
        }
    }

    @Test
    void simulatedClockWakesTheLoopWhenTheSimulationAdvances() throws CartagoException {
        SimulatedClock clock = new SimulatedClock();
        try (Workspace ws = Calls.quiet("main").clock(clock).build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ws.createArtifact("clock", Clock.class, 100);
            ok(ws, agent, "focus", "clock");
            obs.next();
            ok(ws, agent, "start");
            for (int tick = 1; tick <= 3; tick++) {
                awaitSleepers(clock, 1);
                clock.advance(100);
                obs.expect("clock ticks(" + (tick - 1) + ")->ticks(" + tick + ")", "clock !tick[" + tick + "]");
            }
        }
    }

    /** Waits (spinning, with a safety deadline) until the loop sleeps, so that advance() reaches it. */
    private static void awaitSleepers(SimulatedClock clock, int n) {
        long giveUp = System.nanoTime() + 10_000_000_000L;
        while (clock.sleepers() < n) {
            assertTrue(System.nanoTime() < giveUp, "the clock loop never went to sleep");
            Thread.yield();
        }
    }

    @Test
    void steppedSimulatedTimeWakesEachDeadlineOnce() throws CartagoException {
        SimulatedClock clock = new SimulatedClock();
        try (Workspace ws = Calls.quiet("main").stepped().clock(clock).build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ws.createArtifact("clock", Clock.class, 100);
            ok(ws, agent, "focus", "clock");
            ok(ws, agent, "start");
            obs.next();
            clock.advance(99);
            assertEquals(0, ws.runPending());
            clock.advance(1);
            ws.runPending();
            obs.expect("clock ticks(0)->ticks(1)", "clock !tick[1]");
            clock.advance(250);
            ws.runPending();
            obs.expect("clock ticks(1)->ticks(2)", "clock !tick[2]");
            assertEquals(List.of(), obs.drain());
        }
    }

    @Test
    void steppedRunsRepeatExactly() throws CartagoException {
        List<String> first = twoClocks();
        List<String> second = twoClocks();
        assertEquals(first, second);
        assertEquals(5 + 3, first.stream().filter(e -> e.contains("!tick")).count(), first.toString());
        // Both clocks are due at 150; slow queued its wait at 100, fast at 120, so slow goes first.
        assertEquals("150 slow !tick[3]", first.get(first.size() - 2));
        assertEquals("150 fast !tick[5]", first.get(first.size() - 1));
    }

    private static List<String> twoClocks() throws CartagoException {
        SimulatedClock clock = new SimulatedClock();
        List<String> trace = new ArrayList<>();
        try (Workspace ws = Calls.quiet("main").stepped().clock(clock).build()) {
            AgentId agent = ws.join("alice", new ArtifactObserverAdapter() {
                @Override
                public void signalled(ArtifactId artifact, String type, List<Object> args) {
                    trace.add(clock.nowMillis() + " " + artifact.name() + " !" + type + args);
                }
            });
            ws.createArtifact("fast", Clock.class, 30);
            ws.createArtifact("slow", Clock.class, 50);
            ok(ws, agent, "focus", "fast");
            ok(ws, agent, "focus", "slow");
            assertTrue(Calls.call(ws, agent, OpTarget.name("fast"), "start").succeeded());
            assertTrue(Calls.call(ws, agent, OpTarget.name("slow"), "start").succeeded());
            for (int t = 0; t < 15; t++) {
                clock.advance(10);
                ws.runPending();
            }
        }
        return trace;
    }
}
