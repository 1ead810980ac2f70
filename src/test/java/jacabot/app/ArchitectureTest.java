package jacabot.app;

import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** This module's packages depend one way only, and never on a layer above it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        // the application composes every module; inside it, the run drivers, then the benches, then the CLI
        PackageLayers.of("jacabot.app", "run", "bench", "cli").check();
    }
}
