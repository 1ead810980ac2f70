package jacabot.experiments;

import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** This module's packages depend one way only, and never on a layer above it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        // the middleware artifacts: CArtAgO's API and the robot link, nothing of the controller or the world
        PackageLayers.of("jacabot.experiments", "geom", "link", "team", "")
                .mustNotUse("jacabot.app..", "jacabot.agent..", "jacabot.robot", "jacabot.robot.baseline..", "jacabot.robot.run..", "jacabot.sim..").check();
    }
}
