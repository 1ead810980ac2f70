package jacabot.cartago;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;

import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import jacabot.arch.PackageLayers;
import org.junit.jupiter.api.Test;

/** This module's packages depend one way only, and never on a layer above it (see the module's README). */
class ArchitectureTest {
    @Test
    void packagesDependOneWayAndNeverUpwards() {
        PackageLayers.of("jacabot.cartago", "", "tools", "remote", "examples", "bridge")
                .mustNotUse("jacabot.robot..", "jacabot.sim..", "jacabot.experiments..", "jacabot.app..")
                .check();
    }

    @Test
    void onlyTheJacaBridgeKnowsTheAgents() {
        var classes = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_JARS).importPackages("jacabot.cartago");
        noClasses().that().resideOutsideOfPackage("jacabot.cartago.bridge..")
                .should().dependOnClassesThat().resideInAPackage("jacabot.agent..").check(classes);
    }
}
