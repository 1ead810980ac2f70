package jacabot.cartago;

/**
 * An output parameter of an artifact operation, as in CArtAgO: the agent passes an unbound
 * variable, the operation calls {@link #set(Object)}, and the variable is bound when the
 * operation succeeds.
 *
 * @param <T> the type of the value
 */
public final class OpFeedbackParam<T> {
    private T value;
    private boolean set;

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
}
