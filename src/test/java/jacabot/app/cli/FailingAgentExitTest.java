package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An agent that fails at its job ends its experiment at once with exit 1 and one line saying why,
 * at every console level (FailureWatch): an action that does not exist (with or without a failure
 * plan), no plan for its first goal, a failure storm, an initial goal failed and not handled,
 * reasoning that runs away within a control step. The run's folder is still written.
 */
class FailingAgentExitTest {
    /** The initial phase's own recovery: an unknown action fails !start, whose failure plan stops the system. */
    static final String UNKNOWN_ACTION = """
            !start.
            +!start <- setSpeed(1, 2).
            -!start[error_msg(M)] <- println("the robot cannot start: ", M); .stopMAS.
            """;
    /** No failure plan at all: the unknown action's failure drops the intention of !start. */
    static final String UNKNOWN_ACTION_UNHANDLED = """
            !start.
            +!start <- setSpeed(1, 2).
            """;
    /** An initial goal failed with nobody to handle it, though every action exists. */
    static final String INITIAL_GOAL_DROPPED = """
            !start.
            +!start <- !look.
            +!look <- ?landmark(nowhere).
            """;
    static final String NO_PLAN = """
            !start.
            +!other <- stop.
            """;
    /** The failure plan re-posts the goal at once: it fails every reasoning cycle. */
    static final String STORM = """
            !start.
            +!start <- !go.
            +!go <- ?missing(X); !go.
            -!go[error_msg(M)] <- .print(M); !go.
            """;
    /** A goal that re-posts itself, never waiting, never failing: no storm, but the step would never end. */
    static final String RUNAWAY = """
            !start.
            +!start <- !spin.
            @spin +!spin <- !spin.
            """;

    private static void assertFailsWith(Path dir, String agent, String why) throws Exception {
        Path file = dir.resolve("agent.asl");
        Files.writeString(file, agent);
        for (String level : List.of("--quiet", "")) {
            Path out = dir.resolve("out" + level);
            var args = new ArrayList<>(List.of("experiment", "obstacle-avoidance", "--headless", "--duration", "5m",
                    "--agent", file.toString(), "--out", out.toString()));
            if (!level.isEmpty()) {
                args.add(level);
            }
            String[] r = CliRun.run(args.toArray(new String[0]));
            assertEquals("1", r[0], level + ": " + r[1] + r[2]);
            List<String> errors = r[2].lines().filter(l -> l.startsWith("error: ")).toList();
            assertEquals(1, errors.size(), level + ": one line saying why:\n" + r[2]);
            assertTrue(errors.get(0).contains(why), errors.get(0));
            assertFalse(r[2].contains("\tat "), "no stack trace: " + r[2]);
            // ended at once, not after its five minutes, and what it made is written
            String summary = Files.readString(out.resolve("summary.txt"));
            var simulated = Pattern.compile(", ([0-9.]+) s simulated").matcher(summary);
            assertTrue(simulated.find() && Double.parseDouble(simulated.group(1)) < 2, summary);
        }
    }

    @Test
    void anActionThatDoesNotExist(@TempDir Path dir) throws Exception {
        assertFailsWith(dir, UNKNOWN_ACTION, "the agent stopped the system (.stopMAS) at t=0.0 s, before the run's end, "
                + "after goal !start failed (error action_failed, error_msg \"no artifact in workspace main has operation setSpeed/2\", "
                + "at agent.asl:2)");
    }

    @Test
    void anActionThatDoesNotExistWithNoFailurePlan(@TempDir Path dir) throws Exception {
        assertFailsWith(dir, UNKNOWN_ACTION_UNHANDLED, "goal !start failed at t=0.0 s and no plan handles its failure "
                + "(error action_failed, error_msg \"no artifact in workspace main has operation setSpeed/2\", at agent.asl:2): "
                + "the action does not exist");
    }

    @Test
    void anInitialGoalFailedWithNoFailurePlan(@TempDir Path dir) throws Exception {
        assertFailsWith(dir, INITIAL_GOAL_DROPPED, "goal !look failed at t=0.0 s and no plan handles its failure "
                + "(error test_goal_failed, error_msg \"Failed to test 'landmark(nowhere)'\", at agent.asl:3): "
                + "the agent dropped its initial goal !start");
    }

    @Test
    void noPlanForTheFirstGoal(@TempDir Path dir) throws Exception {
        assertFailsWith(dir, NO_PLAN, "no relevant plan for the agent's initial goal !start");
    }

    @Test
    void aFailureStorm(@TempDir Path dir) throws Exception {
        assertFailsWith(dir, STORM, "failure storm at t=0.0 s: goal !go failed 1000 times within one simulated second "
                + "(error test_goal_failed, error_msg \"Failed to test 'missing(X)'\", at agent.asl:3)");
    }

    @Test
    void reasoningThatRunsAwayWithinAStep(@TempDir Path dir) throws Exception {
        assertFailsWith(dir, RUNAWAY, "reasoning ran away in control step 0 at t=0.00 s: 20000 reasoning cycles without "
                + "going idle (a plan that loops without waiting, or an action failing again and again), running @spin; "
                + "the run stops here");
    }
}
