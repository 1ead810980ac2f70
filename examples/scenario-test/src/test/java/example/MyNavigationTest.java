package example;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.scenario.Scenario;
import jacabot.app.scenario.ScenarioResult;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/**
 * A user's scenario test: my navigation agent, in the thesis' navigation world, must pick a
 * cylinder within 40 simulated seconds, and do so the same way under the same seed.
 * (Run with the project's tests: `gradle test`; see examples/scenario-test/README.md.)
 */
class MyNavigationTest {
    /** This example's folder; the tests run in the repository's root. */
    static final Path HERE = Path.of(System.getProperty("jacabot.rootDir", "."), "examples", "scenario-test");

    @Test
    void myAgentPicksACylinder() throws Exception {
        ScenarioResult r = Scenario.of("navigation")
                .agent(HERE.resolve("my-navigation.asl"))
                .world(HERE.resolve("../../worlds/navigation.json"))
                .seed(3)
                .duration(Duration.ofSeconds(40))
                .run();
        assertTrue(r.summary().picks() >= 1, "no pick in 40 s:\n" + r.eventLog());
        assertFalse(r.consoleLines("Cylinder picked up").isEmpty(), String.join("\n", r.console()));

        ScenarioResult again = Scenario.of("navigation").agent(HERE.resolve("my-navigation.asl"))
                .world(HERE.resolve("../../worlds/navigation.json")).seed(3).duration(Duration.ofSeconds(40)).run();
        assertEquals(r.eventLog(), again.eventLog(), "same seed, same run");
    }
}
