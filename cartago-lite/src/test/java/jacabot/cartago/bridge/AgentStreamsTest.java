package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import jacabot.agent.semantics.Clock;
import jacabot.agent.runtime.LocalMAS;
import java.io.PrintStream;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Each agent of a project draws from its own random stream (bidders of a contract net must not
 * all wait alike), and the streams repeat under the same seed.
 */
class AgentStreamsTest {
    private static List<Double> firstDraws(long seed, int agents) throws Exception {
        var mas = new LocalMAS(Clock.wall(), new PrintStream(OutputStream.nullOutputStream()), seed);
        var parser = new AslParser();
        var draws = new ArrayList<Double>();
        for (int i = 0; i < agents; i++) {
            var ag = mas.createAgent("bidder" + i, parser.parse("", "bidder.asl"), parser, null);
            draws.add(ag.random().nextDouble());
        }
        return draws;
    }

    @Test
    void agentsOfOneSeedDrawApartAndRepeat() throws Exception {
        List<Double> draws = firstDraws(0, 5);
        // java.util.Random seeded 0..4 gives first doubles within 0.001 of each other
        double min = draws.stream().mapToDouble(d -> d).min().orElseThrow();
        double max = draws.stream().mapToDouble(d -> d).max().orElseThrow();
        assertTrue(max - min > 0.1, "first draws " + draws);
        assertEquals(5, new HashSet<>(draws).size());
        assertEquals(draws, firstDraws(0, 5));
        assertTrue(!draws.equals(firstDraws(1, 5)));
    }
}
