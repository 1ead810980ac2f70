package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.ConsoleFile;
import jacabot.app.inspector.Inspector;
import jacabot.app.replay.PageEdits;
import jacabot.app.replay.StepArchive;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A lockstep experiment writes its console with simulated times (console.txt), and the inspector
 * serves it by time: every line the agent printed, in order, at the instant it printed it, with
 * the event log's lines among them.
 */
class ConsoleFileOfARunTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    /** The thesis' agent as published: near a wall it prints "Obstacle: N", "Wait avoiding" in a loop. */
    private static final String PUBLISHED = ROOT.resolve("agents/src/main/asl/as-published/suspend-resume.asl").toString();

    @Test
    void theAgentsLinesAndTheEventLogByTimeFromARecordedRun(@TempDir Path dir) throws Exception {
        Path run = dir.resolve("run");
        String[] r = CliRun.run("experiment", "suspend-resume", "--headless", "--duration", "40s", "--verbose",
                "--agent", PUBLISHED, "--out", run.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        List<String> file = Files.readAllLines(run.resolve(ConsoleFile.FILE));
        assertFalse(StepArchive.open(run, (t, x, z) -> {
        }).header().realTime(), "a lockstep run's step log");
        List<String> printed = r[1].lines().filter(l -> l.startsWith("[robot] ")).toList();
        assertTrue(printed.size() >= 4, r[1]);
        // every line the agent printed, in order, each with a time
        assertEquals(printed, file.stream().filter(l -> l.matches("t=\\d+\\.\\d{3} \\[robot\\] .*"))
                .map(l -> l.substring(l.indexOf(' ') + 1)).toList());
        // the event log's lines, in order, among them
        List<String> events = Files.readAllLines(run.resolve(ConsoleFile.EVENT_LOG));
        assertEquals(events, file.stream().filter(events::contains).toList());
        long previous = 0;
        for (String l : file) {
            long t = Math.round(Double.parseDouble(l.substring(2, l.indexOf(' '))) * 1000);
            assertTrue(t >= previous && t <= 40_000, "in time order, within the run: " + l);
            assertTrue(t % 40 == 0 || !l.contains("[robot]"), "an agent prints at a control step's time: " + l);
            previous = t;
        }

        var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        try (Inspector inspector = Inspector.startOnFreePort()) {
            inspector.console(ConsoleFile.of(run));
            long from = 10_000, to = 30_000;
            var expected = new ArrayList<String>();
            for (String l : file) {
                long t = Math.round(Double.parseDouble(l.substring(2, l.indexOf(' '))) * 1000);
                if (t >= from && t <= to) {
                    expected.add(t + " " + l.substring(l.indexOf(' ') + 1));
                }
            }
            assertTrue(expected.size() >= 2, "the published agent prints between 10 s and 30 s: " + file);
            JsonNode range = get(client, inspector.url("api/console?from=" + from + "&to=" + to));
            assertEquals(expected, lines(range));
            // a window around an instant: the last lines at or before it, then the first after it
            long at = Long.parseLong(expected.get(1).split(" ")[0]);
            JsonNode window = get(client, inspector.url("api/console?t=" + at + "&before=2&after=1"));
            List<String> shown = lines(window);
            assertEquals(3, shown.size(), shown.toString());
            assertTrue(Long.parseLong(shown.get(1).split(" ")[0]) <= at && Long.parseLong(shown.get(2).split(" ")[0]) > at, shown.toString());
            assertTrue(window.get("earlier").asBoolean() && window.get("later").asBoolean(), window.toString());
            var bad = client.send(HttpRequest.newBuilder(URI.create(inspector.url("api/console?from=soon"))).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertEquals(400, bad.statusCode());
        }
    }

    /** The agent's clock, not the wall's: lines printed after .wait(1000) and .wait(2000) more carry those simulated times. */
    @Test
    void anAgentsLineCarriesTheSimulatedTimeItWasPrintedAt(@TempDir Path dir) throws Exception {
        Path agent = dir.resolve("waits.asl");
        Files.writeString(agent, "!go.\n+!go <- .wait(1000); .print(\"after one second\"); .wait(2000); .print(\"after three\").\n");
        Path run = dir.resolve("run");
        String[] r = CliRun.run("experiment", "suspend-resume", "--headless", "--duration", "5s", "--agent", agent.toString(),
                "--out", run.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        var c = ConsoleFile.of(run);
        var lines = c.between(0, Long.MAX_VALUE, 100).stream().filter(l -> l.text().startsWith("[robot] after")).toList();
        assertEquals(2, lines.size(), lines.toString());
        assertTrue(lines.get(0).timeMs() >= 1000 && lines.get(0).timeMs() <= 1080, lines.toString());
        assertTrue(lines.get(1).timeMs() >= 3000 && lines.get(1).timeMs() <= 3160, lines.toString());
    }

    /**
     * A real-time run (here without the viewer: the same run) writes console.txt as a lockstep run
     * does: the agent's lines at the simulated time they were printed, the event log's among them.
     */
    @Test
    void aRealTimeRunWritesItsConsoleByItsSimulatedTimeToo(@TempDir Path dir) throws Exception {
        Path agent = dir.resolve("waits.asl");
        Files.writeString(agent, "!go.\n+!go <- .wait(1000); .print(\"after one second\"); .wait(2000); .print(\"after three\").\n");
        // experiment 1's world with its first event (a box moved) at 2 s instead of 20 s
        var world = (ObjectNode) new ObjectMapper().readTree(ROOT.resolve("worlds/obstacle-avoidance.json").toFile());
        ((ObjectNode) world.get("events").get(0)).put("at", 2);
        Path worldFile = Files.writeString(dir.resolve("obstacle-avoidance.json"), world.toString());
        Path run = dir.resolve("run");
        String[] r = CliRun.run("experiment", "obstacle-avoidance", "--real-time", "--headless", "--no-inspector",
                "--duration", "4s", "--agent", agent.toString(), "--world", worldFile.toString(), "--out", run.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        assertTrue(r[1].contains(", console.txt"), "the run names it among what it wrote: " + r[1]);
        var lines = ConsoleFile.of(run).between(0, Long.MAX_VALUE, 1000);
        var said = lines.stream().filter(l -> l.text().startsWith("[robot] after")).toList();
        assertEquals(2, said.size(), lines.toString());
        // the world goes on while the agent wakes: a step or a few later in real time
        assertTrue(said.get(0).timeMs() >= 1000 && said.get(0).timeMs() <= 1400, said.toString());
        assertTrue(said.get(1).timeMs() >= 3000 && said.get(1).timeMs() <= 3400, said.toString());
        List<String> file = Files.readAllLines(run.resolve(ConsoleFile.FILE));
        List<String> events = Files.readAllLines(run.resolve(ConsoleFile.EVENT_LOG));
        assertTrue(!events.isEmpty(), "the run has events");
        assertEquals(events, file.stream().filter(events::contains).toList(), "the event log's lines, in order, among them");
        // its step log says it was in real time: no what-if from it (it could not be made again step for step)
        String[] whatIf = CliRun.run("replay", run.toString(), "--what-if", "1s", "--agent", agent.toString());
        assertEquals("2", whatIf[0], whatIf[1] + whatIf[2]);
        assertTrue(whatIf[2].startsWith("error: ") && whatIf[2].contains("a what-if needs a lockstep run's step log")
                && whatIf[2].strip().lines().count() == 1, whatIf[2]);
        try (Inspector inspector = Inspector.startOnFreePort()) { // nor from its page under replay --inspector
            var h = StepArchive.open(run, (t, x, z) -> {
            }).header();
            assertTrue(h.realTime());
            String refusal = PageEdits.recorded(inspector, run, h, () -> null).whatIfRefusal();
            assertTrue(refusal != null && refusal.contains("lockstep run's step log"), refusal);
        }
    }

    private static JsonNode get(HttpClient client, String url) throws Exception {
        var answer = client.send(HttpRequest.newBuilder(URI.create(url)).build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(200, answer.statusCode(), answer.body());
        return new ObjectMapper().readTree(answer.body());
    }

    private static List<String> lines(JsonNode answer) {
        var out = new ArrayList<String>();
        answer.get("lines").forEach(l -> out.add(l.get("timeMs").asLong() + " " + l.get("text").asText()));
        return out;
    }
}
