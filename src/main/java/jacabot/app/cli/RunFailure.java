package jacabot.app.cli;

/**
 * A run that failed at its job (an agent that cannot start, stopped the system or fell into a
 * failure storm): the launcher prints its message as one line and exits with 1, without a stack
 * trace. What the run made is written before it is thrown.
 */
final class RunFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    RunFailure(String message) {
        super(message, null, false, false);
    }
}
