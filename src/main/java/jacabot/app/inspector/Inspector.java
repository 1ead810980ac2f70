package jacabot.app.inspector;

import static jacabot.app.inspector.Replies.json;
import static jacabot.app.inspector.Replies.query;
import static jacabot.app.inspector.Replies.send;
import static jacabot.app.inspector.Replies.sendJson;
import static jacabot.app.inspector.Replies.sendText;
import static jacabot.app.inspector.Replies.time;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpHandler;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BiFunction;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The mind inspector: a web page on loopback showing each agent's beliefs, events, intentions,
 * plan library and deliberation trace, and for a robot its body, the middleware's commands and a
 * drawing of the arena at the same instant, as Jason's web mind inspector does. Served by the
 * JDK's {@code com.sun.net.httpserver}; the page follows the run through server-sent events
 * ({@code /api/stream}: every kept frame with the deliberation up to it, nothing polled) and reads
 * the past through {@code /api/state?agent=A&t=MS}. The agents' threads only put immutable frames
 * into each {@link MindHistory}; the server's threads only read them. Beside the frames: the
 * {@link Debugger}'s controls ({@code /api/debug}), the time views over the whole run
 * ({@code /api/timeline}, {@code /api/belief}, {@code /api/artifacts}: {@link TimeViews}) and, when
 * the run allows it ({@link RunEdits}), what-ifs and plan reloads ({@code /api/whatif},
 * {@code /api/reload}; both {@link RunControls}), and the run's console by simulated time ({@code /api/console}, read from
 * its file: {@link ConsoleFile}). Every agent added is a history of its own: a team's robots, or a what-if
 * beside the run it came from.
 *
 * <p>Guarded as Jupyter is: every request must carry the run's secret token (the address printed
 * at the start holds it: {@code ?token=...}; the page then keeps it in a cookie), come from no
 * other web page (its {@code Origin}, when sent, is the page's own) and name the inspector's own
 * address as its {@code Host} (no DNS rebinding). Anything else is refused with 403 and logged.
 */
public final class Inspector implements AutoCloseable {
    /** The port tried first (Jason's inspector uses 3272); when taken, any free port. */
    public static final int DEFAULT_PORT = 3273;
    /** Frames kept in memory per agent (older ones are read from the step log when there is one). */
    public static final int HISTORY = 500;
    /** Selections shown in the deliberation table. */
    static final int SELECTIONS = 60;
    /** At most this many pushes per second per page (the run may be much faster than real time). */
    static final int PUSHES_PER_SECOND = 5;

    private final HttpServer server;
    private final ExecutorService threads;
    private final PageGuard guard;
    private volatile Consumer<String> refusals = System.err::println;
    private volatile Object world;
    private final RunControls controls;
    private volatile Supplier<Map<String, ArtifactInfo>> workspace = Map::of;
    private final Map<String, MindHistory> agents = new LinkedHashMap<>();
    private final List<String> paths = new ArrayList<>();
    private volatile Path plotDir;
    private volatile ConsoleFile console;
    private volatile String title = "jacabot";
    private volatile boolean closed;

    private Inspector(HttpServer server) {
        this.server = server;
        this.guard = new PageGuard(server.getAddress());
        this.threads = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "inspector-http");
            t.setDaemon(true);
            return t;
        });
        server.setExecutor(threads);
        this.controls = new RunControls(threads);
        context("/", this::page);
        context("/help.html", ex -> send(ex, 200, "text/html; charset=utf-8", resource("help.html")));
        context("/api/agents", ex -> sendJson(ex, agentNames()));
        context("/api/state", this::state);
        context("/api/history", this::history);
        context("/api/plans", ex -> sendJson(ex, historyOf(ex).map(MindHistory::plans).orElse(List.of())));
        context("/api/world", ex -> sendJson(ex, world));
        context("/api/path", ex -> withHistory(ex, (h, t) -> h.pathUpTo(t)));
        context("/api/selections", ex -> withHistory(ex, (h, t) -> h.selectionsUpTo(t, SELECTIONS)));
        context("/api/debug", controls::debug);
        context("/api/failures", ex -> sendJson(ex, historyOf(ex).map(MindHistory::failures).orElse(Map.of())));
        context("/api/stream", this::stream);
        context("/api/timeline", ex -> withHistory(ex, (h, t) -> timeline(h)));
        context("/api/belief", ex -> withHistory(ex, (h, t) -> beliefHistory(h, query(ex).getOrDefault("name", ""))));
        context("/api/artifacts", ex -> sendJson(ex, artifacts(time(query(ex).get("t")))));
        context("/api/workspace", ex -> sendJson(ex, workspace.get()));
        context("/api/source", ex -> sendJson(ex, Map.of("text", controls.source())));
        context("/api/whatif", controls::whatIf);
        context("/api/reload", controls::reload);
        context("/api/console", this::console);
        context("/plots/", this::plot);
        server.start();
    }

    /**
     * Starts an inspector on loopback.
     *
     * @param port the port, or 0 for {@link #DEFAULT_PORT} if free and any free port otherwise
     */
    public static Inspector start(int port) throws IOException {
        return start(null, port);
    }

    /**
     * Starts an inspector on {@code host} (null: loopback; another address only when the user
     * asks for it, e.g. to look from another machine: the token still guards it).
     */
    public static Inspector start(String host, int port) throws IOException {
        InetAddress loopback = host == null ? InetAddress.getLoopbackAddress() : InetAddress.getByName(host);
        if (port == 0) {
            try {
                return new Inspector(HttpServer.create(new InetSocketAddress(loopback, DEFAULT_PORT), 0));
            } catch (BindException e) {
                return new Inspector(HttpServer.create(new InetSocketAddress(loopback, 0), 0));
            }
        }
        return new Inspector(HttpServer.create(new InetSocketAddress(loopback, port), 0));
    }

    /** Starts an inspector on any free loopback port (tests, several runs at once). */
    public static Inspector startOnFreePort() throws IOException {
        return new Inspector(HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0));
    }

    /** {@return the page's base address, without the token: requests to it alone are refused} */
    public URI uri() {
        return URI.create("http://" + guard.hostName() + ":" + server.getAddress().getPort() + "/");
    }

    /** {@return the page's address with its secret token, to print for the user} */
    public URI address() {
        return URI.create(uri() + "?token=" + guard.token());
    }

    /** {@return {@code path} (no leading slash, may have a query) on this inspector, with the token} */
    public String url(String path) {
        return uri() + path + (path.contains("?") ? "&" : "?") + "token=" + guard.token();
    }

    /** Where refused requests are logged (default: stderr). */
    public void logRefusals(Consumer<String> log) {
        this.refusals = log;
    }

    /** Lets the page halt, step and continue the run, and set breakpoints. */
    public void debugger(Debugger d) {
        controls.debugger = d;
    }

    /** Lets the page start what-ifs from any instant (and reload plans into a live run). */
    public void edits(RunEdits e) {
        controls.edits = e;
    }

    /** {@return the what-ifs started from the page} */
    public List<WhatIfJob> whatIfs() {
        return List.copyOf(controls.whatIfs);
    }

    /** The timeline read last, per agent, and up to when: a recorded run's is read once. */
    private final Map<MindHistory, Map.Entry<Long, List<TimeViews.Span>>> timelines = new ConcurrentHashMap<>();

    private List<TimeViews.Span> timeline(MindHistory h) {
        long upTo = h.range()[1];
        var known = timelines.get(h);
        if (known != null && known.getKey() == upTo) {
            return known.getValue();
        }
        var t = new TimeViews.Timeline();
        h.forEachMind(t::add);
        List<TimeViews.Span> spans = t.spans();
        timelines.put(h, Map.entry(upTo, spans));
        return spans;
    }

    private static List<TimeViews.Change> beliefHistory(MindHistory h, String name) {
        var b = new TimeViews.BeliefHistory(name);
        if (!name.isBlank()) {
            h.forEachMind(b::add);
        }
        return b.changes();
    }

    /** {@return every artifact perceived at {@code t} (ms; -1 the latest): by artifact, each agent's view of its properties} */
    private Map<String, Map<String, List<String>>> artifacts(long t) {
        var out = new TreeMap<String, Map<String, List<String>>>();
        for (String name : agentNames()) {
            MindHistory h;
            synchronized (this) {
                h = agents.get(name);
            }
            MindHistory.Frame f = t < 0 ? h.latest() : h.at(t);
            if (f != null) {
                TimeViews.artifacts(f.mind()).forEach((a, props) -> out.computeIfAbsent(a, k -> new LinkedHashMap<>()).put(name, props));
            }
        }
        return out;
    }

    /** A live run's artifacts now, by name: their operations and who focuses on them (the artifacts panel). */
    public void workspace(Supplier<Map<String, ArtifactInfo>> artifacts) {
        this.workspace = artifacts;
    }

    /** The world the page draws under the robot: its geometry at the start (any JSON-writable value). */
    public void world(Object start) {
        this.world = start;
    }

    /** Adds an agent; its frames go into the returned history. */
    public synchronized MindHistory add(String agent) {
        return agents.computeIfAbsent(agent, a -> new MindHistory(a, HISTORY));
    }

    /** Serves the run's plots (PNG files of this folder) under {@code /plots/}. */
    public void showPlots(Path dir) {
        this.plotDir = dir;
    }

    /** Serves the run's console lines by time ({@code /api/console}), read from its file on demand. */
    public void console(ConsoleFile lines) {
        this.console = lines;
    }

    /** {@code GET /api/console}: the run's console lines around an instant or over a stretch of time ({@link ConsoleFile#answer}). */
    private void console(HttpExchange ex) throws IOException {
        ConsoleFile c = console;
        try {
            sendJson(ex, c == null ? Map.of("available", false, "lines", List.of()) : c.answer(query(ex)));
        } catch (IllegalArgumentException e) {
            sendText(ex, 400, e.getMessage());
        }
    }

    /** Names the run in the page's title. */
    public void title(String text) {
        this.title = text;
    }

    @Override
    public void close() {
        closed = true;
        synchronized (this) {
            agents.values().forEach(h -> {
                synchronized (h) {
                    h.notifyAll();
                }
            });
        }
        server.stop(0);
        threads.shutdownNow();
    }

    // ---- the guard -------------------------------------------------------------------------------------

    /** {@return every path the inspector serves (the guard's test tries each)} */
    List<String> paths() {
        return List.copyOf(paths);
    }

    private void context(String path, HttpHandler handler) {
        paths.add(path);
        server.createContext(path, ex -> {
            String why = guard.refusal(ex, query(ex).get("token"));
            if (why != null) {
                refusals.accept("inspector: refused " + ex.getRequestMethod() + " " + ex.getRequestURI().getPath() + " from "
                        + ex.getRemoteAddress().getAddress().getHostAddress() + ": " + why);
                send(ex, 403, "text/plain", ("403 forbidden: " + why + "\n").getBytes(StandardCharsets.UTF_8));
                return;
            }
            if (guard.token().equals(query(ex).get("token"))) {
                // the page's own later requests (images, fetches) carry it as a cookie
                ex.getResponseHeaders().add("Set-Cookie", guard.cookie());
            }
            handler.handle(ex);
        });
    }

    // ---- handlers ---------------------------------------------------------------------------------

    private synchronized List<String> agentNames() {
        return new ArrayList<>(agents.keySet());
    }

    private synchronized Optional<MindHistory> historyOf(HttpExchange ex) {
        String name = query(ex).get("agent");
        if (name == null && !agents.isEmpty()) {
            name = agents.keySet().iterator().next();
        }
        return Optional.ofNullable(name == null ? null : agents.get(name));
    }

    private void page(HttpExchange ex) throws IOException {
        if (!ex.getRequestURI().getPath().equals("/")) {
            send(ex, 404, "text/plain", "not found".getBytes(StandardCharsets.UTF_8));
            return;
        }
        try (InputStream in = Inspector.class.getResourceAsStream("inspector.html")) {
            String html = new String(in.readAllBytes(), StandardCharsets.UTF_8).replace("{{title}}", escapeHtml(title))
                    .replace("{{token}}", guard.token());
            send(ex, 200, "text/html; charset=utf-8", html.getBytes(StandardCharsets.UTF_8));
        }
    }

    private void state(HttpExchange ex) throws IOException {
        var h = historyOf(ex);
        if (h.isEmpty()) {
            send(ex, 404, "text/plain", "no such agent".getBytes(StandardCharsets.UTF_8));
            return;
        }
        String at = query(ex).get("frame");
        String t = query(ex).get("t");
        MindHistory.Frame f;
        try {
            f = t != null ? h.get().at(Long.parseLong(t)) : at == null ? h.get().latest() : h.get().frame(Long.parseLong(at));
        } catch (NumberFormatException e) {
            send(ex, 400, "text/plain", ("bad frame or time '" + (t != null ? t : at) + "'").getBytes(StandardCharsets.UTF_8));
            return;
        }
        sendJson(ex, f);
    }

    /** Answers {@code what(history, t)} for the agent and time ({@code t}, ms; default the latest) of the query. */
    private void withHistory(HttpExchange ex, BiFunction<MindHistory, Long, Object> what) throws IOException {
        var h = historyOf(ex);
        if (h.isEmpty()) {
            send(ex, 404, "text/plain", "no such agent".getBytes(StandardCharsets.UTF_8));
            return;
        }
        String t = query(ex).get("t");
        long time;
        try {
            time = t == null ? Long.MAX_VALUE : Long.parseLong(t);
        } catch (NumberFormatException e) {
            send(ex, 400, "text/plain", ("bad time '" + t + "'").getBytes(StandardCharsets.UTF_8));
            return;
        }
        sendJson(ex, what.apply(h.get(), time));
    }

    private void history(HttpExchange ex) throws IOException {
        var h = historyOf(ex);
        if (h.isEmpty()) {
            send(ex, 404, "text/plain", "no such agent".getBytes(StandardCharsets.UTF_8));
            return;
        }
        var out = new HashMap<String, Object>();
        out.put("timeline", h.get().timeline());
        out.put("range", h.get().range());
        out.put("selections", h.get().selections());
        sendJson(ex, out);
    }

    /** Server-sent events: the latest frame of every agent, whenever one changes (at most a few per second). */
    private void stream(HttpExchange ex) throws IOException {
        ex.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
        ex.getResponseHeaders().set("Cache-Control", "no-cache");
        ex.sendResponseHeaders(200, 0);
        try (OutputStream out = ex.getResponseBody()) {
            Map<String, Long> seen = new HashMap<>();
            String debugSeen = "";
            while (!closed) {
                boolean sent = false;
                String debugNow = json(controls.debugState());
                if (!debugNow.equals(debugSeen)) {
                    debugSeen = debugNow;
                    out.write(("event: debug\ndata: " + debugNow + "\n\n").getBytes(StandardCharsets.UTF_8));
                    sent = true;
                }
                for (String name : agentNames()) {
                    MindHistory h;
                    synchronized (this) {
                        h = agents.get(name);
                    }
                    long v = h.version();
                    MindHistory.Frame latest = h.latest();
                    if (seen.getOrDefault(name, -1L) != v && latest != null) {
                        seen.put(name, v);
                        long t = latest.mind().timeMs();
                        var push = Map.of("agent", name, "frame", latest, "range", h.range(), "selections",
                                h.selectionsUpTo(t, SELECTIONS), "failures", h.failures().get("count"));
                        out.write(("event: frame\ndata: " + json(push) + "\n\n").getBytes(StandardCharsets.UTF_8));
                        sent = true;
                    }
                }
                if (sent) {
                    out.flush();
                    Thread.sleep(1000 / PUSHES_PER_SECOND);
                } else {
                    out.write(": idle\n\n".getBytes(StandardCharsets.UTF_8)); // finds a closed page
                    out.flush();
                    List<String> names = agentNames();
                    MindHistory first;
                    synchronized (this) {
                        first = names.isEmpty() ? null : agents.get(names.get(0));
                    }
                    if (first != null) {
                        first.awaitChange(seen.getOrDefault(names.get(0), -1L), 250);
                    } else {
                        Thread.sleep(200);
                    }
                }
            }
        } catch (IOException | InterruptedException e) {
            // the page went away, or the inspector stops
        }
    }

    private void plot(HttpExchange ex) throws IOException {
        Path dir = plotDir;
        String name = ex.getRequestURI().getPath().substring("/plots/".length());
        if (dir == null || !name.matches("[A-Za-z0-9_-]+\\.png") || !Files.isRegularFile(dir.resolve(name))) {
            send(ex, 404, "text/plain", "no such plot".getBytes(StandardCharsets.UTF_8));
            return;
        }
        send(ex, 200, "image/png", Files.readAllBytes(dir.resolve(name)));
    }

    // ---- plumbing -------------------------------------------------------------------------------------

    private static byte[] resource(String name) throws IOException {
        try (InputStream in = Inspector.class.getResourceAsStream(name)) {
            return in.readAllBytes();
        }
    }

    private static String escapeHtml(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
