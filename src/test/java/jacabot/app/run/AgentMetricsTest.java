package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.run.AgentMetrics;
import jacabot.robot.Experiment;
import java.util.Set;
import org.junit.jupiter.api.Test;

class AgentMetricsTest {
    @Test
    void countsPlansContextConditionsAndCoordinationBeliefs() throws Exception {
        var m = AgentMetrics.of(Experiment.OBSTACLE_AVOIDANCE, """
                // a comment line is not code
                !go.
                +!go : a & not b | c < 2 <- +avoiding; -+counter(1); if (x) { -picking }.
                +!other <- true.
                """);
        assertEquals(3, m.codeLines());
        assertEquals(2, m.plans());
        assertEquals(1, m.contexts());
        assertEquals(3, m.conditions());
        assertEquals(Set.of("avoiding", "counter", "picking"), m.coordinationBeliefs());
    }

    @Test
    void theAppendixBAgentNeedsMoreCoordinationThanTheAvoidanceAgent() throws Exception {
        var avoid = AgentMetrics.of(Experiment.OBSTACLE_AVOIDANCE, AgentSource.packaged(Experiment.OBSTACLE_AVOIDANCE));
        var full = AgentMetrics.of(Experiment.SUSPEND_RESUME, AgentSource.packaged(Experiment.SUSPEND_RESUME));
        assertTrue(full.coordinationBeliefs().containsAll(Set.of("avoiding", "picking", "delivering", "charging")));
        assertTrue(full.plans() > 3 * avoid.plans() / 2, full.plans() + " vs " + avoid.plans());
    }
}
