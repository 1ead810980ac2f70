package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;

/** Arithmetic with results in output parameters. */
public class Adder extends Artifact {
    @OPERATION
    void add(double a, double b, OpFeedbackParam<Double> sum) {
        sum.set(a + b);
    }

    @OPERATION
    void addAndSubtract(double a, double b, OpFeedbackParam<Double> sum, OpFeedbackParam<Double> difference) {
        sum.set(a + b);
        difference.set(a - b);
    }
}
