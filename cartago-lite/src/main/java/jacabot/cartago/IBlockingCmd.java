package jacabot.cartago;

/**
 * A blocking command (typically I/O) for {@link Artifact#await(IBlockingCmd)}: {@link #exec()} runs
 * while the artifact is released, so it must not touch the artifact's state; it hands its result
 * over through its own fields, read by the operation once {@code await} returns.
 */
public interface IBlockingCmd {
    /** Runs the command; a runtime exception fails the awaiting operation. */
    void exec();
}
