package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import java.util.ArrayDeque;

/** A bounded FIFO queue: put waits while it is full, take while it is empty. */
public class Queue extends Artifact {
    private final ArrayDeque<Object> items = new ArrayDeque<>();
    private int capacity;

    void init(int capacity) {
        this.capacity = capacity;
        defineObsProperty("consumed", 0);
    }

    @OPERATION(guard = "notFull")
    void put(Object item) {
        items.addLast(item);
    }

    @OPERATION(guard = "notEmpty")
    void take(OpFeedbackParam<Object> item) {
        item.set(items.removeFirst());
    }

    /** A consumer says it has dealt with an item. */
    @OPERATION
    void consumed() {
        getObsProperty("consumed").updateValue(getObsProperty("consumed").intValue() + 1);
    }

    // a guard takes the parameters of its operation, as in CArtAgO
    @GUARD
    boolean notFull(Object item) {
        return items.size() < capacity;
    }

    @GUARD
    boolean notEmpty(OpFeedbackParam<Object> item) {
        return !items.isEmpty();
    }
}
