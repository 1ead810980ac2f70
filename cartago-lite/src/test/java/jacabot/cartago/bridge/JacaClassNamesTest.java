package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import jacabot.agent.runtime.MasLauncher;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** CArtAgO's own class names in a .mas2j run as ours; an old jacabot name is refused naming the new one. */
class JacaClassNamesTest {
    @Test
    void cartagosEnvironmentAndArchitectureNamesRun(@TempDir Path dir) throws Exception {
        for (String names : List.of("jaca.CartagoEnvironment|jaca.CAgentArch", "c4jason.CartagoEnvironment|c4jason.CAgentArch")) {
            String[] n = names.split("\\|");
            ProjectRun.write(dir, Map.of("p.mas2j", "MAS p {\n environment: " + n[0] + "\n agents: a agentArchClass " + n[1] + ";\n}\n",
                    "a.asl", "!go.\n+!go <- makeArtifact(\"c\", \"jacabot.cartago.examples.Counter\", [], C); focus(C); inc.\n"
                            + "+count(1) <- println(\"counted\"); .stopMAS.\n"));
            ProjectRun run = ProjectRun.run(dir.resolve("p.mas2j"), 0, 30_000);
            assertEquals(List.of("[a] counted"), run.lines(), names);
        }
    }

    @Test
    void anOldJacabotNameSaysWhereTheClassIsNow(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("p.mas2j"), "MAS p {\n environment: jacabot.cartago.CartagoEnvironment\n agents: a;\n}\n");
        Files.writeString(dir.resolve("a.asl"), "!go.\n");
        var out = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        var e = assertThrows(MasLauncher.UserError.class, () -> new MasLauncher(out, 0, false).load(dir.resolve("p.mas2j")));
        assertEquals("class jacabot.cartago.CartagoEnvironment not found: it is now jacabot.cartago.bridge.CartagoEnvironment", e.getMessage());
    }
}
