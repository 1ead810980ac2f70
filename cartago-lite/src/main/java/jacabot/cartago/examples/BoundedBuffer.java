package jacabot.cartago.examples;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import java.util.ArrayDeque;
import java.util.Deque;

/** CArtAgO's bounded buffer: put waits while full, get while empty; n_items is observable. */
public class BoundedBuffer extends Artifact {
    private final Deque<Object> items = new ArrayDeque<>();
    private int capacity;

    void init(int capacity) {
        this.capacity = capacity;
        defineObsProperty("n_items", 0);
    }

    @OPERATION(guard = "notFull")
    void put(Object item) {
        items.addLast(item);
        getObsProperty("n_items").updateValue(items.size());
    }

    @GUARD
    boolean notFull(Object item) {
        return items.size() < capacity;
    }

    @OPERATION(guard = "notEmpty")
    void get(OpFeedbackParam<Object> item) {
        item.set(items.removeFirst());
        getObsProperty("n_items").updateValue(items.size());
    }

    @GUARD
    boolean notEmpty(OpFeedbackParam<Object> item) {
        return !items.isEmpty();
    }

    /** Waits inside the operation, through await(guard), until the buffer holds n items. */
    @OPERATION
    void waitFor(int n) {
        await("holds", n);
        signal("filled", n);
    }

    @GUARD
    boolean holds(int n) {
        return items.size() >= n;
    }
}
