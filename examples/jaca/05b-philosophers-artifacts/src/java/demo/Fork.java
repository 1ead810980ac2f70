package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;

/** A fork: pick waits until it is free. */
public class Fork extends Artifact {
    private boolean taken;

    @OPERATION(guard = "free")
    void pick() {
        taken = true;
    }

    @OPERATION
    void putDown() {
        if (!taken) {
            failed("the fork is not taken", "not_taken");
        }
        taken = false;
    }

    @GUARD
    boolean free() {
        return !taken;
    }
}
