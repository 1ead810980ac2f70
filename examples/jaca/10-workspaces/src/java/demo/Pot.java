package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;

/** A counter that lives in one workspace: how many times something was stirred. */
public class Pot extends Artifact {
    void init() {
        defineObsProperty("stirred", 0);
    }

    @OPERATION
    void stir() {
        ObsProperty p = getObsProperty("stirred");
        p.updateValue(p.intValue() + 1);
    }
}
