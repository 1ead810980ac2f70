package jacabot.agent.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

class PresortedAnnotsTest {
    private static final List<Term> UNSORTED = List.of(Literal.of("percept_type", Literal.atom("obs_prop")),
            Literal.of("artifact_name", new StringTerm("m")), Literal.SOURCE_PERCEPT,
            Literal.of("artifact_name", new StringTerm("m")), Literal.of("artifact_id", Literal.atom("a1")));

    @Test
    void aLiteralOfPresortedAnnotationsIsTheLiteralOfTheListAsGivenAndKeepsTheList() {
        List<Term> presorted = Literal.presortedAnnots(UNSORTED);
        Literal plain = new Literal("p", List.of(new NumberTerm(1)), UNSORTED, false);
        Literal marked = new Literal("p", List.of(new NumberTerm(1)), presorted, false);
        assertEquals(plain.annots(), presorted, "sorted and without the duplicate");
        assertEquals(4, presorted.size());
        assertEquals(plain, marked);
        assertEquals(marked, plain);
        assertEquals(plain.hashCode(), marked.hashCode());
        assertEquals(plain.toString(), marked.toString());
        assertEquals(0, plain.compareTo(marked));
        assertSame(presorted, marked.annots(), "kept as it is");
        assertSame(presorted, Literal.presortedAnnots(presorted));
        assertThrows(UnsupportedOperationException.class, () -> presorted.set(0, Literal.TRUE));
    }
}
