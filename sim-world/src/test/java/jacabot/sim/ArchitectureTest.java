package jacabot.sim;

import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** This module's packages depend one way only, and never on a layer above it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        PackageLayers.of("jacabot.sim", "geom", "world", "device", "robot", "engine", "io", "", "demo", "viewer")
                .mustNotUse("jacabot.robot..", "jacabot.agent..", "jacabot.cartago..", "jacabot.experiments..", "jacabot.app..").check();
    }
}
