package jacabot.cartago.examples;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;

/** Operations with output parameters. */
public class Calculator extends Artifact {
    @OPERATION
    void sum(double a, double b, OpFeedbackParam<Double> result) {
        result.set(a + b);
    }

    @OPERATION
    void divide(int a, int b, OpFeedbackParam<Integer> quotient, OpFeedbackParam<Integer> remainder) {
        if (b == 0) {
            failed("division by zero", "division_by_zero", a);
        }
        quotient.set(a / b);
        remainder.set(a % b);
    }

    /** Gives back its argument as an Object parameter sees it. */
    @OPERATION
    void echo(Object value, OpFeedbackParam<Object> same) {
        same.set(value);
    }
}
