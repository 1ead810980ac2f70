package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;

/** An artifact whose only operation fails, describing why. */
public class Refuser extends Artifact {
    @OPERATION
    void attempt() {
        log("attempt refused");
        failed("refused on purpose", "refusal", "reason_one", 42);
    }
}
