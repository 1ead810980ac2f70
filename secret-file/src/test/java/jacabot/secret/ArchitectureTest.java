package jacabot.secret;

import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** The secret's file uses nothing of the project: both robot-link and cartago-lite depend on it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        PackageLayers.of("jacabot.secret")
                .mustNotUse("jacabot.robot..", "jacabot.cartago..", "jacabot.agent..", "jacabot.sim..", "jacabot.experiments..", "jacabot.app..").check();
    }
}
