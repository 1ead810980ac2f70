package jacabot.cartago.examples;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;

/** A counter that refuses to go beyond its maximum, given to init. */
public class BoundedCounter extends Artifact {
    private ObsProperty count;
    private int max;

    void init(int max) {
        this.max = max;
        count = defineObsProperty("count", 0);
    }

    @OPERATION
    void inc() {
        int next = count.intValue() + 1;
        count.updateValue(next);
        if (next > max) {
            failed("inc failed: the counter is at its maximum " + max, "max_reached", max);
        }
    }
}
