package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.HttpURLConnection;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The inspector's HTTP side without a browser: pages, JSON, history, the event stream, plots. */
class InspectorServerTest {
    private static MindState mind(long time, String belief, List<MindState.Selection> selections) {
        var b = new MindState.Belief(belief, List.of("percept"), List.of("percept_type(obs_prop)"));
        var im = new MindState.Means("+!go[source(self)]", "@p1 +!go : at(X)", "{X=1}", "move(X)", "!go");
        return new MindState("robot", time, time, time / 10, List.of(b), List.of("+tick"),
                List.of(new MindState.IntentionView(1, "running", List.of(im))), selections);
    }

    @Test
    void servesStatesHistoryStreamAndPlots(@TempDir Path plots) throws Exception {
        var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        try (Inspector inspector = Inspector.startOnFreePort()) {
            assertEquals("127.0.0.1", inspector.uri().getHost());
            MindHistory h = inspector.add("robot");
            var sel = new MindState.Selection(0, 1, 1, "+!go[source(self)]", "@p1 +!go : at(X)", "{X=1}");
            h.record(mind(0, "at(1)", List.of(sel)), new RobotView(0, 0.1, 0.2, 90, null, 1, 2, List.of("stop")), List.of("+!go <- move."));
            h.record(mind(1000, "at(2)", List.of()), null, List.of("+!go <- move."));

            String page = get(client, inspector.address().toString());
            assertTrue(page.contains("<title>") && page.contains("/api/stream"), page);
            assertTrue(page.contains("<link rel=\"icon\" href=\"data:,\">"), "no favicon request that would be refused: " + page);
            assertEquals("[\"robot\"]", get(client, inspector.url("api/agents")));
            String latest = get(client, inspector.url("api/state?agent=robot"));
            assertTrue(latest.contains("at(2)") && latest.contains("\"unifier\":\"{X=1}\""), latest);
            String first = get(client, inspector.url("api/state?agent=robot&frame=0"));
            assertTrue(first.contains("at(1)") && first.contains("\"commands\":[\"stop\"]"), first);
            String history = get(client, inspector.url("api/history?agent=robot"));
            assertTrue(history.contains("\"plan\":\"@p1 +!go : at(X)\""), history);
            assertTrue(get(client, inspector.url("api/plans")).contains("+!go <- move."));
            h.record(mind(2000, "at(3)", List.of(new MindState.Selection(2000, 200, 1,
                    "-!go[code(move),error(action_failed),error_msg(\"blocked\")]", "@p2 -!go", "{}"))), null, List.of());
            String failures = get(client, inspector.url("api/failures?agent=robot"));
            assertTrue(failures.contains("\"count\":1") && failures.contains("error_msg"), failures);
            assertEquals(404, status(client, inspector.url("api/state?agent=nobody")));
            assertEquals(400, status(client, inspector.url("api/state?agent=robot&frame=x")));

            // plots: only PNG files of the run's folder, nothing else
            Files.write(plots.resolve("battery.png"), new byte[] {(byte) 0x89, 'P', 'N', 'G'});
            Files.writeString(plots.resolve("secret.txt"), "no");
            inspector.showPlots(plots);
            assertEquals(200, status(client, inspector.url("plots/battery.png")));
            assertEquals(404, status(client, inspector.url("plots/secret.txt")));
            assertEquals(404, status(client, inspector.url("plots/..%2Fsecret.txt")));

            // the stream sends the latest frame first
            var conn = (HttpURLConnection) URI.create(inspector.url("api/stream")).toURL().openConnection();
            conn.setReadTimeout(10_000);
            try (var in = new BufferedReader(new InputStreamReader(conn.getInputStream(), StandardCharsets.UTF_8))) {
                assertEquals("event: debug", in.readLine(), "first the debugger's state (none here)");
                assertTrue(in.readLine().contains("\"available\":false"));
                assertEquals("", in.readLine());
                assertEquals("event: frame", in.readLine());
                String data = in.readLine();
                assertTrue(data.startsWith("data: ") && data.contains("at(3)") && data.contains("\"failures\":1"), data);
            } finally {
                conn.disconnect();
            }
        }
    }

    @Test
    void refusesRequestsWithoutTheTokenFromAnotherOriginOrWithAnotherRunsToken() throws Exception {
        var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        var refused = new CopyOnWriteArrayList<String>();
        try (Inspector inspector = Inspector.startOnFreePort(); Inspector other = Inspector.startOnFreePort()) {
            inspector.logRefusals(refused::add);
            inspector.add("robot").record(mind(0, "at(1)", List.of()), null, List.of());
            assertTrue(inspector.address().getQuery().matches("token=[0-9a-f]{48}"), inspector.address().toString());
            assertEquals(200, status(client, inspector.url("api/agents")));
            // no token, on the page and on the API
            assertEquals(403, status(client, inspector.uri().toString()));
            assertEquals(403, status(client, inspector.uri() + "api/state?agent=robot"));
            assertEquals(403, status(client, inspector.uri() + "api/stream"));
            // another run's token
            String foreign = other.url("api/agents").replaceAll(".*token=", "");
            assertEquals(403, status(client, inspector.uri() + "api/agents?token=" + foreign));
            // the right token, sent by another web page (its Origin) or for another host name (DNS rebinding)
            var fromElsewhere = HttpRequest.newBuilder(URI.create(inspector.url("api/agents")))
                    .header("Origin", "http://evil.example").build();
            assertEquals(403, client.send(fromElsewhere, HttpResponse.BodyHandlers.discarding()).statusCode());
            // the page's own origin is fine; so is the cookie the page gets with the token
            var own = HttpRequest.newBuilder(URI.create(inspector.url("api/agents")))
                    .header("Origin", "http://127.0.0.1:" + inspector.uri().getPort()).build();
            var answer = client.send(own, HttpResponse.BodyHandlers.discarding());
            assertEquals(200, answer.statusCode());
            String cookie = answer.headers().firstValue("Set-Cookie").orElseThrow().split(";")[0];
            var withCookie = HttpRequest.newBuilder(URI.create(inspector.uri() + "api/agents")).header("Cookie", cookie).build();
            assertEquals(200, client.send(withCookie, HttpResponse.BodyHandlers.discarding()).statusCode());
            assertEquals(5, refused.size(), "each refusal logged: " + refused);
            assertTrue(refused.get(0).contains("no token") && refused.get(3).contains("wrong token")
                    && refused.get(4).contains("another origin"), refused.toString());
            // every endpoint the inspector serves, the console's too: without the token, and with it from another origin
            List<String> paths = inspector.paths();
            assertTrue(paths.containsAll(List.of("/", "/api/state", "/api/stream", "/api/debug", "/api/whatif", "/api/console")), paths.toString());
            for (String path : paths) {
                String p = path.substring(1) + (path.endsWith("/") && path.length() > 1 ? "trajectory.png" : "");
                assertEquals(403, status(client, inspector.uri() + p), "no token: " + path);
                var foreignPage = HttpRequest.newBuilder(URI.create(inspector.url(p))).header("Origin", "http://evil.example").build();
                assertEquals(403, client.send(foreignPage, HttpResponse.BodyHandlers.discarding()).statusCode(), "another origin: " + path);
            }
            assertEquals(5 + 2 * paths.size(), refused.size(), "each refusal logged");
        }
        try (Inspector inspector = Inspector.startOnFreePort()) {
            // DNS rebinding: the right token, for a host name that is not the inspector's (a raw request: the
            // JDK's client will not send a Host of our choosing)
            inspector.logRefusals(refused::add);
            String path = inspector.url("api/agents").replaceFirst("^http://[^/]+", "");
            try (var socket = new Socket("127.0.0.1", inspector.uri().getPort())) {
                socket.getOutputStream().write(("GET " + path + " HTTP/1.1\r\nHost: evil.example:" + inspector.uri().getPort()
                        + "\r\nConnection: close\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
                var in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.US_ASCII));
                assertEquals("HTTP/1.1 403 Forbidden", in.readLine());
            }
            assertTrue(refused.get(refused.size() - 1).contains("another host"), refused.toString());
        }
    }

    /** A page's edits of the run (what-if, reload) are refused as any request is, without the token or from elsewhere. */
    @Test
    void editsOfTheRunAreGuardedToo() throws Exception {
        var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        var received = new CopyOnWriteArrayList<String>();
        var refused = new CopyOnWriteArrayList<String>();
        try (Inspector inspector = Inspector.startOnFreePort(); Inspector other = Inspector.startOnFreePort()) {
            inspector.logRefusals(refused::add);
            inspector.edits(new RunEdits() {
                @Override
                public String source() {
                    return "!start.";
                }

                @Override
                public void whatIf(WhatIfJob job, String program) {
                    received.add("what-if at " + job.getAtMs() + ": " + program);
                    job.done("there", job.getAtMs(), job.getAtMs() + 40);
                }

                @Override
                public String reload(String program) {
                    received.add("reload: " + program);
                    return "applied";
                }
            });
            String foreign = other.url("x").replaceAll(".*token=", "");
            for (String path : List.of("api/whatif?t=1000&seconds=5", "api/reload")) {
                String bare = inspector.uri() + path;
                assertEquals(403, post(client, bare, null), "no token: " + path);
                assertEquals(403, post(client, bare + (path.contains("?") ? "&" : "?") + "token=" + foreign, null), "another run's token");
                assertEquals(403, post(client, inspector.url(path), "http://evil.example"), "another origin");
            }
            assertEquals(List.of(), received, "nothing refused reached the run");
            assertEquals(6, refused.size(), refused.toString());
            String own = "http://127.0.0.1:" + inspector.uri().getPort();
            assertEquals(200, post(client, inspector.url("api/whatif?t=1000&seconds=5"), own));
            assertEquals(200, post(client, inspector.url("api/reload"), own));
            assertEquals(400, post(client, inspector.url("api/whatif?t=x&seconds=5"), own), "a bad instant");
            for (int i = 0; i < 100 && received.size() < 2; i++) {
                Thread.sleep(50);
            }
            assertEquals(List.of("reload: +!go <- move.", "what-if at 1000: +!go <- move."), received.stream().sorted().toList());
            assertEquals("done", inspector.whatIfs().get(0).getState());
            assertTrue(get(client, inspector.url("api/debug")).contains("\"divergesAtMs\":1040"), "the page is told where it differs");
        }
    }

    /**
     * A real-time run's edits: a what-if is refused with why (it needs a lockstep run's step log), a
     * reload answers what happened, a bad program is refused with its location; the page is told which.
     */
    @Test
    void aRealTimeRunsEditsSayWhatHappened() throws Exception {
        var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        var received = new CopyOnWriteArrayList<String>();
        try (Inspector inspector = Inspector.startOnFreePort()) {
            inspector.edits(new RunEdits() {
                @Override
                public String source() {
                    return "!start.";
                }

                @Override
                public void whatIf(WhatIfJob job, String program) {
                    received.add("what-if");
                }

                @Override
                public String whatIfRefusal() {
                    return "a what-if needs a lockstep run's step log";
                }

                @Override
                public Reload reloads() {
                    return Reload.AT_NEXT_CYCLE;
                }

                @Override
                public String reload(String program) {
                    if (program.contains("bad")) {
                        throw new IllegalArgumentException("edited.asl:1:4: no plan here");
                    }
                    received.add("reload");
                    return "applied to the running agent at t = 4.20 s";
                }
            });
            String debug = get(client, inspector.url("api/debug"));
            assertTrue(debug.contains("\"reload\":\"AT_NEXT_CYCLE\"") && debug.contains("lockstep run's step log"), debug);
            var whatIf = send(client, inspector.url("api/whatif?t=1000&seconds=5"), "+!go <- move.");
            assertEquals(409, whatIf.statusCode());
            assertEquals("a what-if needs a lockstep run's step log", whatIf.body().trim());
            var bad = send(client, inspector.url("api/reload"), "bad");
            assertEquals(409, bad.statusCode());
            assertTrue(bad.body().contains("edited.asl:1:4"), bad.body());
            var good = send(client, inspector.url("api/reload"), "+!go <- move.");
            assertEquals(200, good.statusCode());
            assertTrue(good.body().contains("\"message\":\"applied to the running agent at t = 4.20 s\""), good.body());
            assertEquals(List.of("reload"), received, "no what-if started, one reload applied");
            assertTrue(inspector.whatIfs().isEmpty());
        }
    }

    private static HttpResponse<String> send(HttpClient c, String url, String body) throws Exception {
        return c.send(HttpRequest.newBuilder(URI.create(url)).timeout(Duration.ofSeconds(10))
                .POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString());
    }

    @Test
    void timeViewsOverTheWholeHistory() throws Exception {
        var h = new MindHistory("robot", 2);
        var t = new TimeViews.Timeline();
        var b = new TimeViews.BeliefHistory("battery");
        String[] tops = {"@a +!go", "@a +!go", "@b +!charge", "@a +!go"};
        for (int i = 0; i < tops.length; i++) {
            var means = new MindState.Means("+!x", tops[i], "{}", ".wait(1)", "");
            var m = new MindState("robot", i, i * 1000L, i, List.of(new MindState.Belief("battery(" + (i < 2 ? "ok" : "low") + ")",
                    List.of("percept"), List.of("artifact_name(\"body\")"))), List.of(),
                    List.of(new MindState.IntentionView(1, "running", List.of(means))), List.of());
            t.add(m);
            b.add(m);
            h.record(m, null, List.of());
        }
        assertEquals(List.of(new TimeViews.Span(1, "@a +!go", 0, 2000), new TimeViews.Span(1, "@b +!charge", 2000, 3000),
                new TimeViews.Span(1, "@a +!go", 3000, 3000)), t.spans());
        assertEquals(List.of(new TimeViews.Change(0, '+', "battery(ok)"), new TimeViews.Change(2000, '-', "battery(ok)"),
                new TimeViews.Change(2000, '+', "battery(low)")), b.changes());
        assertEquals(Map.of("body", List.of("battery(low)")), TimeViews.artifacts(h.latest().mind()));
    }

    private static int post(HttpClient c, String url, String origin) throws Exception {
        var r = HttpRequest.newBuilder(URI.create(url)).timeout(Duration.ofSeconds(10))
                .POST(HttpRequest.BodyPublishers.ofString("+!go <- move."));
        if (origin != null) {
            r.header("Origin", origin);
        }
        return c.send(r.build(), HttpResponse.BodyHandlers.discarding()).statusCode();
    }

    @Test
    void historyIsBoundedAndKeepsChangesOnly() {
        var h = new MindHistory("robot", 3);
        for (int i = 0; i < 10; i++) {
            h.record(mind(i * 1000, "at(" + i + ")", List.of()), null, List.of());
        }
        assertEquals(3, h.timeline().size());
        assertEquals(9, h.latest().index());
        // the same mind 10 ms later is not a new frame; 250 ms later it is (the robot moves meanwhile)
        h.record(mind(9010, "at(9)", List.of()), null, List.of());
        assertEquals(9, h.latest().index());
        h.record(mind(9000 + MindHistory.KEEP_EVERY_MS, "at(9)", List.of()), null, List.of());
        assertEquals(10, h.latest().index());
    }

    private static String get(HttpClient c, String url) throws Exception {
        var r = c.send(HttpRequest.newBuilder(URI.create(url)).timeout(Duration.ofSeconds(10)).build(),
                HttpResponse.BodyHandlers.ofString());
        assertEquals(200, r.statusCode(), url);
        return r.body();
    }

    private static int status(HttpClient c, String url) throws Exception {
        return c.send(HttpRequest.newBuilder(URI.create(url)).timeout(Duration.ofSeconds(10)).build(),
                HttpResponse.BodyHandlers.discarding()).statusCode();
    }
}
