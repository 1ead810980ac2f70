package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.testing.TestAgent;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A percept's event that no plan is relevant for is made only when a listener hears it
 * ({@link CircumstanceListener#hearsBeliefEvent}; agent-core's README, "How the interpreter is
 * fast"): a {@code .wait} for a time hears none, a {@code .wait} for an event those that may
 * match it, a {@code .wait} for a formula all of them; what each wait does is unchanged.
 */
class UnheardEventTest {

    private static List<String> events(TestAgent a) {
        var out = new ArrayList<String>();
        a.agent.circumstance().eventList().forEach(e -> out.add(e.trigger().toString()));
        return out;
    }

    @Test
    void aWaitForATimeHearsNoPerceptNoPlanIsFor() {
        var a = new TestAgent("""
                !g.
                +!g <- .wait(1000); .print(done).
                +ping <- .print(ping).
                """).cycles(50);
        a.percept("temp(20)").percept("ping").unpercept("temp(20)");
        assertEquals(List.of("+ping[source(percept)]"), events(a), "only the event a plan is for");
        a.cycles(50).advance(1000, 50);
        assertEquals(List.of("ping", "done"), a.printed());
    }

    @Test
    void aListenerThatHearsEveryEventStillGetsThePerceptsNoPlanIsFor() {
        var a = new TestAgent("""
                !g.
                +!g <- .wait(1000).
                """).cycles(50);
        var heard = new ArrayList<String>();
        a.agent.circumstance().addListener(new CircumstanceListener() {
            @Override
            public void eventAdded(Event e) {
                heard.add(e.trigger().toString());
            }
        });
        a.percept("temp(20)").unpercept("temp(20)");
        assertEquals(List.of("+temp(20)[source(percept)]", "-temp(20)[source(percept)]"), heard);
        assertEquals(heard, events(a), "kept, as Jason's with a listener");
        a.cycles(50);
        assertTrue(events(a).isEmpty(), "selected and dropped: no plan is for them");
    }

    @Test
    void aWaitForAnEventHearsThePerceptsThatMayMatchIt() {
        var a = new TestAgent("""
                !g.
                +!g <- .wait("+temp(X)"); .print(got(X)); .wait({-temp(_)}); .print(gone).
                """).cycles(50);
        a.percept("other(1)").unpercept("other(1)");
        assertTrue(events(a).isEmpty(), "another functor: " + events(a));
        a.percept("temp(3)").cycles(50);
        a.percept("temp(3, 4)").cycles(50);
        assertEquals(List.of("got(3)"), a.printed(), "another arity does not end the second wait");
        a.unpercept("temp(3)").cycles(50);
        assertEquals(List.of("got(3)", "gone"), a.printed());
    }

    @Test
    void aWaitForAFormulaIsTestedAtEveryPercept() {
        var a = new TestAgent("""
                !g.
                +!g <- .wait(temp(X) & X > 3); .print(warm(X)).
                """).cycles(50);
        a.percept("temp(2)").cycles(50);
        assertEquals(List.of(), a.printed());
        a.unpercept("temp(2)").percept("temp(5)").cycles(50);
        assertEquals(List.of("warm(5)"), a.printed());
    }
}
