package jacabot.app;

import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** This module's packages depend one way only, and never on a layer above it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        // the application composes every module; inside it: the installation, the generated worlds, the console,
        // the mind inspector, the run drivers, the recorder and replay, the plots, the scenario API, the sweeps,
        // the benches, the CLI (every package listed: one left out would not be checked)
        PackageLayers.of("jacabot.app", "", "world", "console", "inspector", "run", "replay", "plot", "scenario", "sweep",
                "bench", "cli").check();
    }
}
