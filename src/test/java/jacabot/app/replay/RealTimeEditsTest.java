package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Event;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Trigger;
import jacabot.app.console.ConsoleLog;
import jacabot.app.inspector.RunEdits;
import jacabot.app.run.AgentSource;
import java.io.PrintStream;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The page's edit of a live real-time run's plans, without a browser: the agent is driven here
 * cycle by cycle on the test's thread, as its own thread would. The edited plans replace the
 * agent's at the start of its next reasoning cycle, on that thread (not before, not on the
 * page's); a program that does not parse changes nothing and says where it is wrong; an agent that
 * never cycles again gets nothing applied, later either.
 */
class RealTimeEditsTest {
    private static final String PROGRAM = "!hello.\n@hello +!hello <- .print(\"hello from the first plan\").\n";
    private static final String EDITED = "@hello +!hello <- .print(\"hello from the edited plan\").\n";

    private final List<String> printed = new CopyOnWriteArrayList<>();
    private final AtomicLong now = new AtomicLong(12_340);
    private final AtomicReference<Thread> clockReadOn = new AtomicReference<>();
    private final AgentSource source = AgentSource.text("hello.asl", PROGRAM);
    private Agent agent;
    private LocalMAS mas;

    private RealTimeEdits edits(long waitMs) throws Exception {
        PrintStream console = ConsoleLog.lines(printed::add);
        mas = new LocalMAS(() -> now.get(), console, 1);
        var parser = source.parser();
        agent = mas.createAgent("robot", source.parse(parser), parser, null);
        mas.runUntilQuiescent(100);
        assertTrue(printed.stream().anyMatch(l -> l.contains("hello from the first plan")), printed.toString());
        return new RealTimeEdits(source, agent, () -> {
            clockReadOn.set(Thread.currentThread()); // the swap's instant is read where the swap runs
            return now.get();
        }, null, waitMs);
    }

    private void hello() {
        agent.postExternalEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, Literal.atom("hello")), null));
        mas.runUntilQuiescent(100);
    }

    @Test
    @Timeout(30)
    void theEditedPlansReplaceTheAgentsAtItsNextCycleOnItsThread() throws Exception {
        RealTimeEdits edits = edits(10_000);
        assertEquals(RunEdits.Reload.AT_NEXT_CYCLE, edits.reloads());
        assertNotNull(edits.whatIfRefusal());
        assertTrue(edits.whatIfRefusal().contains("lockstep run's step log"), edits.whatIfRefusal());
        List<Plan> before = List.copyOf(agent.planLibrary().plans());
        var page = CompletableFuture.supplyAsync(() -> {
            try {
                return edits.reload(EDITED);
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        // the swap is queued for the agent's next cycle (the agent now has something to do), not done
        for (int i = 0; i < 500 && agent.canSleep(); i++) {
            Thread.sleep(10);
        }
        assertFalse(agent.canSleep(), "a task waits for the agent's next cycle");
        Thread.sleep(100);
        assertFalse(page.isDone(), "nothing is applied before the agent cycles");
        assertEquals(before, agent.planLibrary().plans(), "the plans are the agent's until its next cycle");

        long cycle = agent.cycles() + 1;
        mas.runUntilQuiescent(100); // the agent's cycle, on this thread
        String message = page.get();
        assertEquals(Thread.currentThread(), clockReadOn.get(), "swapped on the agent's thread");
        assertEquals("applied to the running agent at t = 12.34 s: the plans it chooses from its reasoning cycle "
                + cycle + " on are the edited program's", message);
        hello();
        assertEquals("hello from the edited plan", printed.get(printed.size() - 1).replaceAll(".*\\] ", ""), printed.toString());
    }

    @Test
    @Timeout(30)
    void aProgramThatDoesNotParseChangesNothingAndSaysWhere() throws Exception {
        RealTimeEdits edits = edits(10_000);
        List<Plan> before = List.copyOf(agent.planLibrary().plans());
        var e = assertThrows(IllegalArgumentException.class,
                () -> edits.reload("@hello +!hello <- .print(\"edited\").\n@broken +!b <- .print(\"x\") .print(\"y\").\n"));
        assertTrue(e.getMessage().matches("(?s)hello\\.asl:2:\\d+:.*"), e.getMessage());
        assertTrue(agent.canSleep(), "nothing queued for the agent");
        hello();
        assertEquals(before, agent.planLibrary().plans());
        assertTrue(printed.get(printed.size() - 1).endsWith("hello from the first plan"), printed.toString());
    }

    @Test
    @Timeout(30)
    void anAgentThatNeverCyclesGetsNothingLaterEither() throws Exception {
        RealTimeEdits edits = edits(300);
        List<Plan> before = List.copyOf(agent.planLibrary().plans());
        var e = assertThrows(IllegalStateException.class, () -> edits.reload(EDITED));
        assertTrue(e.getMessage().contains("nothing applied"), e.getMessage());
        hello(); // it cycles again: the edit given up is not applied
        assertEquals(before, agent.planLibrary().plans());
        assertTrue(printed.get(printed.size() - 1).endsWith("hello from the first plan"), printed.toString());
    }
}
