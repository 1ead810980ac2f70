package jacabot.agent.parser;

import java.util.List;
import java.util.stream.Collectors;

/** AgentSpeak source that cannot be read; carries every error found, each with its position. */
public final class AslSyntaxException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient List<SyntaxError> errors;

    public AslSyntaxException(List<SyntaxError> errors) {
        super(errors.stream().map(SyntaxError::toString).collect(Collectors.joining("\n")));
        this.errors = List.copyOf(errors);
    }

    public List<SyntaxError> errors() {
        return errors;
    }
}
