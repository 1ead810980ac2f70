package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;

/** run(n): some work holding the artifact (delay), then waits until contributions reach n. */
public class TwoStepJob extends Artifact {
    private int contributed;

    @OPERATION
    void run(int needed) {
        delay(300);   // holds the artifact: no contribute runs meanwhile
        signal("first_step_done", contributed);
        await("enough", needed);   // releases it until the guard holds
        signal("second_step_done", contributed);
    }

    @GUARD
    boolean enough(int needed) {
        return contributed >= needed;
    }

    @OPERATION
    void contribute(int amount) {
        contributed += amount;
    }
}
