package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.testing.TestAgent;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * The probe shows a fact the last capture showed as the same object (agent-core's README, "How
 * the interpreter is fast"), and prints anew a changed fact and one holding a Java object.
 */
class MindProbeCacheTest {

    private static MindState.Belief find(MindState m, String prefix) {
        return m.beliefs().stream().filter(b -> b.literal().startsWith(prefix)).findFirst().orElseThrow();
    }

    @Test
    void anUnchangedFactIsShownAsBeforeAndAChangedOneAnew() {
        var a = new TestAgent("""
                kept(1).
                !g.
                +!g <- -+moved(1).
                """);
        MindProbe probe = MindProbe.attach(a.agent);
        a.cycles(50);
        AtomicInteger counter = new AtomicInteger(1);
        a.agent.addPercept(new Literal("held", List.of(new ObjectTerm(counter)), List.of(Literal.SOURCE_PERCEPT), false));
        MindState first = probe.capture();
        a.percept("moved(2)").unpercept("moved(2)");
        a.agent.addPercept(Literal.of("moved", new NumberTerm(3)).addAnnot(Literal.SOURCE_PERCEPT));
        counter.set(7);
        MindState second = probe.capture();
        assertSame(find(first, "kept"), find(second, "kept"));
        assertEquals("moved(3)[source(percept)]", find(second, "moved(3)").text());
        assertEquals("held(1)", find(first, "held").literal());
        assertEquals("held(7)", find(second, "held").literal(), "a Java object's text is read again");
        assertNotSame(find(first, "held"), find(second, "held"));
    }
}
