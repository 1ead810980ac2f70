package jacabot.agent;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.agent.parser.AgentSpeakLexer;
import jacabot.agent.parser.AgentSpeakParser;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.junit.jupiter.api.Test;

class GrammarWiringTest {
    @Test
    void generatedParserReadsALiteral() {
        var parser = new AgentSpeakParser(new CommonTokenStream(
                new AgentSpeakLexer(CharStreams.fromString("~obstacle(left, 350)"))));
        var literal = parser.literalFile().literal();
        assertEquals(0, parser.getNumberOfSyntaxErrors());
        assertEquals("obstacle", literal.ATOM().getText());
        assertEquals(2, literal.term().size());
    }
}
