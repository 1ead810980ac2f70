package jacabot.agent.parser;

import jacabot.agent.syntax.SourceInfo;
import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;

/** The one funnel for lexer and parser errors: each becomes a {@link SyntaxError} with its position. */
final class ErrorCollector extends BaseErrorListener {
    private final String file;
    private final List<SyntaxError> errors = new ArrayList<>();

    ErrorCollector(String file) {
        this.file = file;
    }

    @Override
    public void syntaxError(Recognizer<?, ?> recognizer, Object offendingSymbol, int line, int col,
            String msg, RecognitionException e) {
        errors.add(new SyntaxError(new SourceInfo(file, line, col + 1), msg));
    }

    void add(SourceInfo where, String message) {
        errors.add(new SyntaxError(where, message));
    }

    List<SyntaxError> errors() {
        return errors;
    }
}
