package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;

/** A counter made by a remote agent in the node's workspace. */
public class Tally extends Artifact {
    void init() {
        defineObsProperty("count", 0);
    }

    @OPERATION
    void bump() {
        ObsProperty count = getObsProperty("count");
        count.updateValue(count.intValue() + 1);
    }
}
