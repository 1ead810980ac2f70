package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.scenario.Scenario;
import jacabot.app.scenario.ScenarioResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A scenario whose agent fails at its job ends at that step and says why
 * ({@link ScenarioResult#agentFailure()}): an unknown action, no plan for the first goal, a failure
 * storm, reasoning that runs away within a step; an agent that works has no failure.
 */
class FailingAgentScenarioTest {
    private static ScenarioResult run(Path dir, String agent) throws Exception {
        Path file = dir.resolve("agent.asl");
        Files.writeString(file, agent);
        return Scenario.of("navigation").agent(file).seed(1).duration(Duration.ofMinutes(5)).run();
    }

    private static void assertFailed(ScenarioResult r, String why) {
        assertTrue(r.agentFailure().isPresent(), r.console().toString());
        assertTrue(r.agentFailure().get().contains(why), r.agentFailure().get());
        assertTrue(r.summary().duration() < 2, "ended at once: " + r.summary().duration() + " s");
    }

    @Test
    void unknownAction(@TempDir Path dir) throws Exception {
        assertFailed(run(dir, """
                !start.
                +!start <- forwardd.
                -!start[error_msg(M)] <- println("the robot cannot start: ", M); .stopMAS.
                """), "no artifact in workspace main has operation forwardd/0");
    }

    @Test
    void noPlanForTheFirstGoal(@TempDir Path dir) throws Exception {
        assertFailed(run(dir, """
                !start.
                +!start : false <- stop.
                """), "no applicable plan for the agent's initial goal !start");
    }

    @Test
    void failureStorm(@TempDir Path dir) throws Exception {
        assertFailed(run(dir, """
                !start.
                +!start <- !turn.
                +!turn <- .fail(error(stuck)).
                -!turn <- !turn.
                """), "failure storm");
    }

    /** A goal re-posted at once, never failing: the step's cap of reasoning cycles ends the run, not a hang. */
    @Test
    void reasoningThatRunsAwayWithinAStep(@TempDir Path dir) throws Exception {
        assertFailed(run(dir, """
                !start.
                +!start <- !spin.
                @spin +!spin <- !spin.
                """), "reasoning ran away in control step 0 at t=0.00 s");
    }

    @Test
    void aRecoveryThatWaitsIsNoStorm(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("agent.asl");
        Files.writeString(file, """
                !start.
                +!start <- !turn.
                +!turn <- .fail.
                -!turn <- .wait(1); !turn.
                """);
        ScenarioResult r = Scenario.of("navigation").agent(file).seed(1).duration(Duration.ofSeconds(3)).run();
        assertTrue(r.agentFailure().isEmpty(), r.agentFailure().toString());
        assertEquals(3, r.summary().duration(), 0.1);
    }
}
