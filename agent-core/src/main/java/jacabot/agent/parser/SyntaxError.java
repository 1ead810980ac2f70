package jacabot.agent.parser;

import jacabot.agent.syntax.SourceInfo;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;

/** One static error in AgentSpeak source, printed as {@code file:line:col: error: message}. */
public record SyntaxError(SourceInfo where, String message) {
    /**
     * {@return an ANTLR message of another of the project's grammars (.mas2j) in the words
     * AgentSpeak's errors use: "unexpected '=', expected ';' or '['", not the grammar's token set}
     */
    public static String inOurWords(String antlrMessage, Recognizer<?, ?> recognizer, RecognitionException e) {
        return ErrorCollector.inAgentSpeak(antlrMessage, recognizer, e);
    }

    @Override
    public String toString() {
        return where + ": error: " + message;
    }
}
