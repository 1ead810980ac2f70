package jacabot.agent.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/** {@link LocalMAS#runSimulated}: time jumps to the next timer when every agent is idle, and only then. */
class SimulatedTimeTest {
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final SimulatedTime time = new SimulatedTime();
    private final LocalMAS mas = new LocalMAS(time, new PrintStream(bytes, true, StandardCharsets.UTF_8), 1);
    private final AslParser parser = new AslParser();

    private void agent(String name, String source) throws Exception {
        mas.createAgent(name, parser.parse(source, name + ".asl"), parser, null);
    }

    private List<String> lines() {
        return bytes.toString(StandardCharsets.UTF_8).lines().toList();
    }

    @Test
    void aLongWaitTakesNoRealTime() throws Exception {
        agent("a", """
                !go.
                +!go <- .system_time(T0); .wait(5000); .system_time(T1); .time(H, M, S); .print(T1 - T0, " ", H, ":", M, ":", S);
                        .stopMAS.
                """);
        long start = System.nanoTime();
        assertTrue(mas.runSimulated(time));
        long realMs = (System.nanoTime() - start) / 1_000_000;
        assertEquals(List.of("[a] 5000 0:0:5"), lines());
        assertEquals(5000, time.millis());
        assertTrue(realMs < 1000, realMs + " ms of real time");
    }

    @Test
    void timeStandsStillWhileAnyAgentWorks() throws Exception {
        // on the wall clock the 1 ms wait ends long before the other agent's 20000 cycles
        agent("waiter", """
                !go.
                +!go <- .send(worker, achieve, count(20000)); .wait(1); .send(worker, askOne, done(D), A); .print(A).
                """);
        agent("worker", """
                +!count(0) <- +done(yes).
                +!count(N) <- !!count(N - 1).
                """);
        assertFalse(mas.runSimulated(time));
        assertEquals(List.of("[waiter] done(yes)[source(worker)]"), lines());
        assertEquals(1, time.millis());
    }

    @Test
    void nothingToWaitForEndsTheRunAtOnce() throws Exception {
        // no timer and no agent to post +never: on the wall clock this would wait for a watchdog
        agent("a", """
                !go.
                +!go <- .wait({+never}); .print(unreachable).
                """);
        long start = System.nanoTime();
        assertFalse(mas.runSimulated(time));
        assertTrue((System.nanoTime() - start) / 1_000_000 < 1000);
        assertEquals(List.of(), lines());
        assertEquals(0, time.millis());
    }

    @Test
    void stopMasWithADelayStopsInSimulatedTime() throws Exception {
        agent("a", """
                !go.
                +!go <- .stopMAS(3000).
                +jag_shutting_down(T) <- .print(shutting_down(T)).
                """);
        long start = System.nanoTime();
        assertTrue(mas.runSimulated(time));
        assertTrue((System.nanoTime() - start) / 1_000_000 < 1000);
        assertEquals(List.of("[a] shutting_down(3000)"), lines());
        assertEquals(3000, time.millis());
        assertTrue(mas.isStopped());
    }
}
