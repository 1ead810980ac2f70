package jacabot.experiments.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.ControllerConfig;
import jacabot.robot.link.Command;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Readings;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/**
 * The middleware's turn taken on the controller's simulation thread ({@link CallerTurn}): the
 * step's frames reach the middleware in order and are answered on that thread, a run is the one
 * its two reading threads would make, and the reading thread takes the stream back for the goodbye.
 */
class CallerTurnTest {
    /** A scripted agent side: logs each event with the thread it came on, answers each step. */
    private static final class Answering implements Consumer<LinkEvent> {
        final List<String> events = new CopyOnWriteArrayList<>();
        final List<Thread> stepThreads = new CopyOnWriteArrayList<>();
        final CountDownLatch disconnected = new CountDownLatch(1);
        volatile Thread disconnectThread;
        MiddlewareLink link;

        @Override
        public void accept(LinkEvent e) {
            if (e instanceof LinkEvent.Reading r) {
                events.add("reading " + r.step() + " " + Readings.format(r.info()));
            } else if (e instanceof LinkEvent.StepMarker m) {
                events.add("marker " + m.step());
                stepThreads.add(Thread.currentThread());
                List<Command> answer = m.step() == 0 ? List.of(Command.setSpeeds(30, 40))
                        : m.step() == 5 ? List.of(Command.turnLeft()) : List.of();
                link.answerStep(answer, m.step());
            } else if (e instanceof LinkEvent.Disconnected d) {
                events.add("disconnected " + d.reason());
                disconnectThread = Thread.currentThread();
                disconnected.countDown();
            }
        }
    }

    /** Runs ten lockstep steps of the navigation world on this thread; {@return the agent side's record} */
    private static Answering run(boolean turns) throws Exception {
        var agent = new Answering();
        var config = ControllerConfig.defaults().withLockstep(true).withLog(line -> { });
        try (var ends = BothEnds.start(LinkTestSupport.world("navigation"), config,
                LinkConfig.defaults().withLog(line -> { }), turns)) {
            agent.link = ends.middleware();
            ends.middleware().handOver(agent);
            ends.controller().runner().runFor(0.4); // ten steps, on this thread
            assertEquals(10, ends.controller().steps());
            ends.controller().close();
            assertTrue(agent.disconnected.await(LinkTestSupport.DEADLINE_S, TimeUnit.SECONDS), "the goodbye is read");
            assertEquals(2, ends.middleware().timings().response().count(), "both commands reported as applied");
        }
        return agent;
    }

    @Test
    void eachStepIsReadAndAnsweredOnTheSimulationThreadAndTheGoodbyeOnTheReadingThread() throws Exception {
        Answering agent = run(true);
        assertEquals(10, agent.stepThreads.size());
        agent.stepThreads.forEach(t -> assertEquals(Thread.currentThread(), t, "the step's turn ran on the simulation thread"));
        assertNotEquals(Thread.currentThread(), agent.disconnectThread, "the reading thread took the stream back");
        assertTrue(agent.events.get(agent.events.size() - 1).contains("said goodbye"), agent.events.toString());
        // every frame in order: each step's readings, then its marker; the answer in effect at the next step
        long step = -1;
        for (String e : agent.events) {
            if (e.startsWith("reading ")) {
                long s = Long.parseLong(e.split(" ")[1]);
                assertEquals(step + 1, s, "readings of the step after the last marker: " + e);
            } else if (e.startsWith("marker ")) {
                step = Long.parseLong(e.substring(7));
            }
        }
        assertEquals(9, step);
        assertTrue(agent.events.contains("reading 1 WHEEL_SPEEDS=[30.0,40.0]"), agent.events.toString());
    }

    @Test
    void theTurnsGiveTheEventsTheTwoReadingThreadsGive() throws Exception {
        Answering threads = run(false);
        Answering turns = run(true);
        assertNotEquals(Thread.currentThread(), threads.stepThreads.get(0), "without turns the reading thread answers");
        assertEquals(threads.events, turns.events);
    }

    @Test
    void aTurnWhoseConnectionIsNeverLentGivesUpAndEveryConnectionReadsOnItsOwnThread() throws Exception {
        var turn = new CallerTurn(200);
        turn.enable();
        long t0 = System.nanoTime();
        assertFalse(turn.take(new InetSocketAddress(InetAddress.getLoopbackAddress(), 1), 0), "no such connection");
        assertTrue(System.nanoTime() - t0 >= TimeUnit.MILLISECONDS.toNanos(200), "it waited for the handshake to end");
        try (var socket = new Socket()) {
            var config = LinkConfig.defaults().withSecret(LinkSecret.random());
            var c = new RobotConnection(socket, null, config, new LinkCosts(), turn);
            assertNull(turn.lend(c), "released: a connection reads on its own thread at once");
        }
    }
}
