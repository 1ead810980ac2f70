package jacabot.agent.parser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class PlainTermTest {
    private final AslParser parser = new AslParser();

    @Test
    void readsPlainAtomsAndNumbersAsTheGrammarDoes() throws Exception {
        for (String text : List.of("x", "x42", "aB_9", "begin", "end", "tell", "0", "42", "007", "4.25", "10.0",
                "12345678901234567890")) {
            Term plain = PlainTerm.read(text);
            assertNotNull(plain, text);
            Term parsed = parser.parseTermByGrammar(text);
            assertEquals(parsed, plain, text);
            assertEquals(parsed.getClass(), plain.getClass(), text);
            assertEquals(parsed.toString(), plain.toString(), text);
        }
        // functors are interned, as the grammar's
        assertSame(((Literal) parser.parseTermByGrammar("x42")).functor(), ((Literal) PlainTerm.read("x42")).functor());
    }

    @Test
    void leavesEverythingElseToTheGrammar() {
        for (String text : List.of("", "X", "_", "_x", "div", "mod", "not", "true", "false", "if", "while", "4.", ".5",
                "1e3", "x y", " x", "x ", "f(x)", "\"s\"", "'q'", "a.b", "-1", "1.2.3", "x::y", "~x", "x[a]")) {
            assertNull(PlainTerm.read(text), text);
        }
    }

    @Test
    void agreesWithTheGrammarOnRandomTexts() throws Exception {
        var random = new Random(7);
        String alphabet = "abzAZ09_.";
        int plain = 0;
        for (int k = 0; k < 20_000; k++) {
            var sb = new StringBuilder();
            for (int i = 1 + random.nextInt(6); i > 0; i--) {
                sb.append(alphabet.charAt(random.nextInt(alphabet.length())));
            }
            String text = sb.toString();
            Term quick = PlainTerm.read(text);
            if (quick != null) {
                plain++;
                assertEquals(parser.parseTermByGrammar(text), quick, text);
            }
        }
        assertEquals(true, plain > 2_000, "plain texts among the random ones: " + plain);
    }
}
