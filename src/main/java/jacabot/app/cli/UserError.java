package jacabot.app.cli;

/**
 * A mistake of the user's (a bad option, a file that cannot be read or written, a world that cannot
 * run): the launcher prints its message as one line and exits with 2, without a stack trace. Every
 * command's user errors come through here ({@link JacabotCommand}'s handler), so that each is one
 * {@code error: ...} line, or the {@code file:line:col: error: ...} line of a syntax error.
 */
final class UserError extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final boolean located;

    UserError(String message) {
        this(message, false);
    }

    private UserError(String message, boolean located) {
        super(message, null, false, false);
        this.located = located;
    }

    /** {@return an error whose message already starts with its place and says error (a parser's line)} */
    static UserError located(String line) {
        return new UserError(line, true);
    }

    /** {@return the line to print} */
    String line() {
        return located ? getMessage() : "error: " + getMessage();
    }
}
