package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** As in Jason, an agent's source named without extension ({@code waiter waiter2 ...}) is waiter2.asl. */
class AgentFileNameTest {
    @Test
    void aSourceNamedWithoutExtensionIsAnAslFile(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("t.mas2j", """
                MAS t {
                    environment: jacabot.cartago.bridge.CartagoEnvironment
                    agents: waiter waiter2 agentArchClass jacabot.cartago.bridge.CAgentArch;
                }
                """, "waiter2.asl", "!go.\n+!go <- .my_name(Me); println(Me, \" runs waiter2\"); .stopMAS.\n"));
        assertEquals("[waiter] waiter runs waiter2\n", ProjectRun.run(dir.resolve("t.mas2j"), 0, 90_000).output);
    }
}
