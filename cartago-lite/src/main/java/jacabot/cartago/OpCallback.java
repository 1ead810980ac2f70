package jacabot.cartago;

/**
 * Receives the outcome of one operation call, exactly once. In threaded mode it runs on the thread
 * that ran the operation; in stepped mode on the thread calling {@link Workspace#runPending()}.
 * It must return quickly and must not block.
 */
@FunctionalInterface
public interface OpCallback {
    /** Called once when the operation has ended. */
    void completed(OpOutcome outcome);
}
