package jacabot.agent.parser;

import jacabot.agent.syntax.SourceInfo;

/** One static error in AgentSpeak source, printed as {@code file:line:col: error: message}. */
public record SyntaxError(SourceInfo where, String message) {
    @Override
    public String toString() {
        return where + ": error: " + message;
    }
}
