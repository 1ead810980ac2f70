package jacabot.cartago.examples;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;

/** The counter of the thesis (Chapter 2, section 4.2), as written there. */
public class Counter extends Artifact {
    void init() {
        defineObsProperty("count", 0);
    }

    @OPERATION
    void inc() {
        ObsProperty prop = getObsProperty("count");
        prop.updateValue(prop.intValue() + 1);
        signal("tick");
    }
}
