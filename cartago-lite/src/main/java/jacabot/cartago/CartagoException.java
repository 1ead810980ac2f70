package jacabot.cartago;

/** A workspace request from Java code that failed; {@link #failure()} says why, as agents would see it. */
public final class CartagoException extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient OpOutcome.Failure failure;

    CartagoException(OpOutcome.Failure failure) {
        super(failure.message());
        this.failure = failure;
    }

    /** {@return the failure, with its reason term} */
    public OpOutcome.Failure failure() {
        return failure;
    }
}
