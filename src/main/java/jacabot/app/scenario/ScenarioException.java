package jacabot.app.scenario;

/** A scenario that cannot start: a bad world file or agent; the message says where (file:line:col). */
public final class ScenarioException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public ScenarioException(String message, Throwable cause) {
        super(message, cause);
    }
}
