package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Routing between an agent's workspaces, and the failures of the workspace actions. */
class WorkspacesTest {
    private static final String MAS2J = "MAS w {\n environment: jacabot.cartago.bridge.CartagoEnvironment\n"
            + " agents: a agentArchClass jacabot.cartago.bridge.CAgentArch; b agentArchClass jaca.CAgentArch;\n}\n";

    private static List<String> run(Path dir, String a, String b) throws Exception {
        ProjectRun.write(dir, Map.of("w.mas2j", MAS2J, "a.asl", a, "b.asl", b));
        ProjectRun run = ProjectRun.run(dir.resolve("w.mas2j"), 0, 90_000);
        assertTrue(run.stopped, run.output);
        return run.lines();
    }

    @Test
    void annotationsAndIdsChooseTheWorkspaceAndFailuresSayWhy(@TempDir Path dir) throws Exception {
        String a = """
                !go.
                +!go
                  <- createWorkspace("w1");
                     !again;
                     joinWorkspace("w1", W1);
                     out(here, 1);
                     out(here, 0) [wsp("main")];
                     rd(here, X) [wsp_id(W1)];
                     println("w1 holds ", X);
                     rd(here, Y) [wsp("main")];
                     println("main holds ", Y);
                     !missing(W1);
                     quitWorkspace;
                     !twice;
                     .send(b, achieve, look).
                +!again <- createWorkspace("w1").
                -!again[env_failure_reason(R)] <- println("again: ", R).
                +!missing(W) <- rd(nothing_here) [wsp("nowhere")].
                -!missing(W)[env_failure_reason(R)] <- println("nowhere: ", R).
                +!twice <- quitWorkspace; quitWorkspace.
                -!twice[env_failure_reason(R), error_msg(M)] <- .println("twice: ", R, " ", M); !anywhere.
                +!anywhere <- println("lost").
                -!anywhere[env_failure_reason(R), error_msg(M)] <- .println("then: ", R, " ", M).
                """;
        String b = """
                +!look
                  <- rd(here, Z);
                     println("b in main reads ", Z);
                     cartago.current_wsps(L);
                     .length(L, N);
                     println("b is in ", N, " workspace(s)");
                     .stopMAS.
                """;
        assertEquals(List.of("[a] again: workspace_exists(\"w1\")", "[a] w1 holds 1", "[a] main holds 0",
                "[a] nowhere: not_joined(\"nowhere\")",
                "[a] twice: not_joined(\"\") the agent is in no such workspace",
                "[a] then: not_joined(\"\") the agent has quit every workspace",
                "[b] b in main reads 0", "[b] b is in 1 workspace(s)"), run(dir, a, b));
    }
}
