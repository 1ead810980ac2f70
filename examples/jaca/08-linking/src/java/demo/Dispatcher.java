package demo;

import jacabot.cartago.ARTIFACT_INFO;
import jacabot.cartago.Artifact;
import jacabot.cartago.ArtifactConfig;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OUTPORT;
import jacabot.cartago.OpFeedbackParam;

/** Forwards work to whatever is linked to its out port "sink". */
@ARTIFACT_INFO(outports = {@OUTPORT(name = "sink")})
public class Dispatcher extends Artifact {
    @OPERATION
    void forward() {
        execLinkedOp("sink", "add", 5);
    }

    @OPERATION
    void readBack(OpFeedbackParam<Integer> total) {
        execLinkedOp("sink", "total", total);
        log("read back " + total.get());
    }

    /** Makes its own accumulator and uses it through its id. */
    @OPERATION
    void spawnAndUse(OpFeedbackParam<Integer> total) {
        ArtifactId own = makeArtifact("own_acc", "demo.Accumulator", new ArtifactConfig(100));
        execLinkedOp(own, "add", 1);
        execLinkedOp(own, "total", total);
    }
}
