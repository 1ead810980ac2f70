package jacabot.agent;

import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** This module's packages depend one way only, and never on a layer above it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        // the interpreter stands alone, as Jason does: no artifacts, no robot, no world
        PackageLayers.of("jacabot.agent", "syntax", "parser", "semantics", "stdlib", "runtime", "testing")
                .mustNotUse("jacabot.cartago..", "jacabot.robot..", "jacabot.sim..", "jacabot.experiments..", "jacabot.app..")
                .check();
    }
}
