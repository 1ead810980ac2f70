package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;

/** A tally that refuses to pass its cap. */
public class CappedTally extends Artifact {
    private int cap;

    void init(int cap) {
        this.cap = cap;
        defineObsProperty("count", 0);
    }

    @OPERATION
    void inc() {
        ObsProperty count = getObsProperty("count");
        if (count.intValue() >= cap) {
            failed("the cap is reached", "inc_failed", "cap_reached", count.intValue());
        }
        count.updateValue(count.intValue() + 1);
    }
}
