package jacabot.cartago;

/**
 * Unwinds an operation that failed, carrying the failure to the runtime; thrown by
 * {@link Artifact#failed(String)} and by the runtime itself. Control flow, not an error: it has no
 * stack trace. Artifact code should not catch it (nor catch {@code RuntimeException} around
 * {@code failed}).
 */
class OpFailedException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final transient OpOutcome.Failure failure;

    OpFailedException(OpOutcome.Failure failure) {
        super(failure.message(), null, false, false);
        this.failure = failure;
    }

    OpFailedException(String message, String functor, Object... args) {
        this(OpOutcome.Failure.of(message, functor, args));
    }

    OpOutcome.Failure failure() {
        return failure;
    }
}
