package jacabot.app.cli;

/**
 * A mistake of the user's (a bad option, a file that cannot be read or written, a world that cannot
 * run): the launcher prints its message as one line and exits with 2, without a stack trace.
 */
final class UserError extends RuntimeException {
    private static final long serialVersionUID = 1L;

    UserError(String message) {
        super(message);
    }
}
