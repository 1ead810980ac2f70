package jacabot.cartago;

/**
 * One completed operation in a workspace's operation log ({@link Workspace#recordOperations}):
 * which operation ({@code name/arity}) ran on the artifact, for which agent ({@code ""} when none),
 * from {@code startMillis} to {@code endMillis} on the workspace's clock (simulated time in a
 * simulated run), and how it ended ({@code failure}: the reason's functor, or the message when it gave none;
 * {@code ""} on success).
 */
public record OperationRecord(long startMillis, long endMillis, String agent, String operation, boolean succeeded,
        String failure) {
}
