package jacabot.robot.link;

import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** This module's packages depend one way only, and never on a layer above it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        // the protocol both ends speak: nothing of the controller, the world or the middleware
        PackageLayers.of("jacabot.robot.link")
                .mustNotUse("jacabot.robot", "jacabot.robot.baseline..", "jacabot.robot.run..", "jacabot.sim..", "jacabot.agent..", "jacabot.cartago..", "jacabot.experiments..", "jacabot.app..").check();
    }
}
