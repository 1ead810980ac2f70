package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import jacabot.app.inspector.ConsoleFile;
import jacabot.app.replay.Replay;
import java.io.IOException;
import java.net.ConnectException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code jacabot replay RUN --headless --inspector}, the command itself on a run it has just
 * recorded: it prints the page's address with its token, serves the page and its APIs with the
 * token (the first step's frame, the mind at an instant, the run's console) and refuses them
 * without it, and quits cleanly, closing its port.
 */
class ReplayInspectorCommandTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    @Timeout(120)
    void servesARecordedRunHeadlessBehindItsTokenAndQuitsCleanly(@TempDir Path dir) throws Exception {
        Path run = dir.resolve("run");
        // 10 s, 250 steps: the command reads every instant on demand from the step log
        ServedReplay.record("navigation", "10s", 2, run);
        Replay recorded = Replay.open(run);
        var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        URI address;
        try (ServedReplay served = ServedReplay.start(run)) {
            address = served.address();
            assertEquals("127.0.0.1", address.getHost(), served.output());
            assertTrue(address.getQuery().matches("token=[0-9a-f]{48}"), address.toString());
            assertTrue(served.output().contains("The recorded run, 0.0 s to 10.0 s, is served at "), served.output());
            String base = "http://127.0.0.1:" + address.getPort() + "/";
            String token = address.getQuery();

            // the page, with the token
            var page = get(client, address.toString());
            assertEquals(200, page.statusCode());
            assertTrue(page.body().contains("replay of " + run) && page.body().contains("/api/stream"), page.body());
            assertEquals("[\"robot\"]", get(client, base + "api/agents?" + token).body());

            // the frame at t = 0 is the run's first step: its time and the robot's pose as the step log has them
            Replay.Frame first = recorded.frames().get(0);
            JsonNode atStart = json(get(client, base + "api/state?agent=robot&t=0&" + token));
            assertEquals(first.timeMs(), atStart.get("mind").get("timeMs").asLong(), atStart.toString());
            assertEquals(first.body().x(), atStart.get("robot").get("x").asDouble(), 1e-9);
            assertEquals(first.body().z(), atStart.get("robot").get("z").asDouble(), 1e-9);

            // the mind at an instant: the step at or before 6 s, its beliefs and its reasoning cycle
            Replay.Frame at6 = recorded.frames().get(recorded.indexAt(6_000));
            JsonNode mind = json(get(client, base + "api/state?agent=robot&t=6000&" + token)).get("mind");
            assertEquals(at6.timeMs(), mind.get("timeMs").asLong());
            assertEquals(at6.mind().cycle(), mind.get("cycle").asLong());
            assertEquals(at6.mind().beliefs().size(), mind.get("beliefs").size());
            assertEquals(at6.mind().beliefs().get(0).literal(), mind.get("beliefs").get(0).get("literal").asText());

            // the console: every line of the run's console file, by time
            List<String> file = Files.readAllLines(run.resolve(ConsoleFile.FILE));
            assertTrue(file.stream().anyMatch(l -> l.contains("[robot] ")), "the agent printed something: " + file);
            JsonNode console = json(get(client, base + "api/console?from=0&to=10000&" + token));
            assertEquals(file.size(), console.get("lines").size(), console.toString());
            String firstAgentLine = file.stream().filter(l -> l.contains("[robot] ")).findFirst().orElseThrow();
            assertTrue(console.toString().contains(JSON.writeValueAsString(firstAgentLine.substring(firstAgentLine.indexOf(' ') + 1))),
                    console.toString());

            // without the token, or with it from another web page: refused, each of them
            for (String path : List.of("", "api/agents", "api/state?agent=robot&t=0", "api/console?from=0&to=10000",
                    "api/stream", "help.html")) {
                assertEquals(403, get(client, base + path).statusCode(), "no token: " + path);
                var foreign = HttpRequest.newBuilder(URI.create(base + path + (path.contains("?") ? "&" : "?") + token))
                        .header("Origin", "http://evil.example").build();
                assertEquals(403, client.send(foreign, HttpResponse.BodyHandlers.discarding()).statusCode(), "another origin: " + path);
            }
            // each refusal told to the user on the command's own output, a line each, no stack trace
            List<String> refusals = served.output().lines().filter(l -> l.contains("refused")).toList();
            assertEquals(12, refusals.size(), served.output());
            assertTrue(refusals.stream().allMatch(l -> l.matches("warning: inspector: refused GET /\\S* from 127\\.0\\.0\\.1: .+")),
                    refusals.toString());
            assertTrue(refusals.get(0).endsWith("no token (open the address printed at the start, with its ?token=...)"), refusals.get(0));
            assertTrue(refusals.get(1).contains("another origin (http://evil.example)"), refusals.get(1));
            assertTrue(!served.output().contains("\tat ") && !served.output().contains("Exception"), served.output());
            assertEquals(-1, served.exitCode(), "still serving");
            served.close();
            assertEquals(0, served.exitCode(), "a quit is a clean end: " + served.output());
        }
        // its port is closed
        assertThrows(ConnectException.class, () -> client.send(HttpRequest.newBuilder(address).build(),
                HttpResponse.BodyHandlers.discarding()));
    }

    private static HttpResponse<String> get(HttpClient client, String url) throws IOException, InterruptedException {
        return client.send(HttpRequest.newBuilder(URI.create(url)).build(), HttpResponse.BodyHandlers.ofString());
    }

    private static JsonNode json(HttpResponse<String> r) throws IOException {
        assertEquals(200, r.statusCode(), r.body());
        return JSON.readTree(r.body());
    }
}
