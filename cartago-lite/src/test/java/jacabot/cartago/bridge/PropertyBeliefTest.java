package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The bridge finds the belief of a changed property by its name and arguments, not by making it
 * anew (agent-core's README, "How the interpreter is fast"): the belief that goes is the one of
 * the property that changed, also when several properties share a name.
 */
class PropertyBeliefTest {

    /** Two properties called {@code v}, told apart by their values. */
    public static class Twins extends Artifact {
        void init() {
            defineObsProperty("v", 1);
            defineObsProperty("v", 2);
            defineObsProperty("w", "a", 2.5);
        }

        @OPERATION
        void bump() {
            getObsPropertyByTemplate("v", 2).updateValue(3);
            getObsProperty("w").updateValues("b", 2.5);
        }

        @OPERATION
        void drop() {
            removeObsPropertyByTemplate("v", 1);
        }
    }

    @Test
    void theBeliefOfTheChangedPropertyGoesAndTheOthersStay() throws Exception {
        var h = new JacaHarness().agent("user", """
                !go.
                +!go <- makeArtifact("t", "%s", [], T); focus(T);
                        .findall(X, v(X), L1); .print(L1); bump;
                        .findall(X, v(X), L2); .findall(p(A, B), w(A, B), W); .print(L2, W); drop;
                        .findall(X, v(X), L3); .print(L3).
                """.formatted(Twins.class.getName())).run(10_000);
        // percepts go to the front of the belief base: the newest first
        assertEquals(List.of("[user] [2,1]", "[user] [3,1][p(\"b\",2.5)]", "[user] [3]"), h.lines());
    }
}
