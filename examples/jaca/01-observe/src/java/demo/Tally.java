package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;

/** A tally that everyone focusing it sees grow, with a signal at each step. */
public class Tally extends Artifact {
    void init() {
        defineObsProperty("count", 0);
    }

    @OPERATION
    void inc() {
        getObsProperty("count").updateValue(getObsProperty("count").intValue() + 1);
        signal("ticked");
    }
}
