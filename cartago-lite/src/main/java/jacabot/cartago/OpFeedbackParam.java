package jacabot.cartago;

/**
 * An output parameter of an artifact operation, as in CArtAgO: the agent passes an unbound
 * variable, the operation calls {@link #set(Object)}, and the variable is bound when the
 * operation succeeds.
 *
 * <p>Callers of {@link Workspace#execOp} pass a fresh instance for each unbound variable; it is
 * the runtime's marker for an output, and after a success its value is both readable here and
 * reported in {@link OpOutcome.Success#outputs()} under the argument's index. The fields are
 * volatile because the value is set on the operation's thread and read by the caller's.
 *
 * @param <T> the type of the value
 */
public final class OpFeedbackParam<T> {
    private volatile T value;
    private volatile boolean set;

    /** Gives the output value; setting it twice keeps the last value, as CArtAgO does. */
    public void set(T value) {
        this.value = value;
        this.set = true;
    }

    /** {@return the value set by the operation, or null} */
    public T get() {
        return value;
    }

    /** {@return whether the operation has set a value} */
    public boolean isSet() {
        return set;
    }

    /** Prints the value, or {@code _} while unset (an unbound variable). */
    @Override
    public String toString() {
        return set ? String.valueOf(value) : "_";
    }
}
