package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.LINK;
import jacabot.cartago.OpFeedbackParam;

/** Adds up what linked artifacts send it; agents cannot call its @LINK operations. */
public class Accumulator extends Artifact {
    private int sum;

    void init() {
    }

    void init(int start) {
        sum = start;
    }

    @LINK
    void add(int amount) {
        sum += amount;
    }

    @LINK
    void total(OpFeedbackParam<Integer> total) {
        total.set(sum);
    }
}
