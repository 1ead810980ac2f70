package jacabot.app.inspector;

import com.fasterxml.jackson.databind.ObjectMapper;
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
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
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
 * {@code /api/reload}), and the run's console by simulated time ({@code /api/console}, read from
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

    private static final ObjectMapper JSON = new ObjectMapper();

    private final HttpServer server;
    private final ExecutorService threads;
    private final PageGuard guard;
    private volatile Consumer<String> refusals = System.err::println;
    private volatile Object world;
    private volatile Debugger debugger;
    private volatile RunEdits edits;
    private volatile Supplier<Map<String, ArtifactInfo>> workspace = Map::of;
    private final List<WhatIfJob> whatIfs = new CopyOnWriteArrayList<>();
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
        context("/", this::page);
        context("/help.html", ex -> send(ex, 200, "text/html; charset=utf-8", resource("help.html")));
        context("/api/agents", ex -> sendJson(ex, agentNames()));
        context("/api/state", this::state);
        context("/api/history", this::history);
        context("/api/plans", ex -> sendJson(ex, historyOf(ex).map(MindHistory::plans).orElse(List.of())));
        context("/api/world", ex -> sendJson(ex, world));
        context("/api/path", ex -> withHistory(ex, (h, t) -> h.pathUpTo(t)));
        context("/api/selections", ex -> withHistory(ex, (h, t) -> h.selectionsUpTo(t, SELECTIONS)));
        context("/api/debug", this::debug);
        context("/api/failures", ex -> sendJson(ex, historyOf(ex).map(MindHistory::failures).orElse(Map.of())));
        context("/api/stream", this::stream);
        context("/api/timeline", ex -> withHistory(ex, (h, t) -> timeline(h)));
        context("/api/belief", ex -> withHistory(ex, (h, t) -> beliefHistory(h, query(ex).getOrDefault("name", ""))));
        context("/api/artifacts", ex -> sendJson(ex, artifacts(time(query(ex).get("t")))));
        context("/api/workspace", ex -> sendJson(ex, workspace.get()));
        context("/api/source", ex -> sendJson(ex, Map.of("text", edits == null ? "" : edits.source())));
        context("/api/whatif", this::whatIf);
        context("/api/reload", this::reload);
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
        this.debugger = d;
    }

    /** The debugger's state: where the run is halted (or null) and the breakpoints. */
    private Map<String, Object> debugState() {
        Debugger d = debugger;
        var out = new LinkedHashMap<String, Object>();
        out.put("available", d != null);
        Debugger.State s = d == null ? null : d.state();
        // the page shows no state older than the one it shows (a command's answer may come after a push)
        out.put("version", s == null ? 0 : s.version());
        Debugger.Halt h = s == null ? null : s.halted();
        out.put("halted", h == null ? null : Map.of("timeMs", h.timeMs(), "reason", h.reason(), "mind", h.mind()));
        out.put("breakpoints", s == null ? List.of() : s.breakpoints());
        RunEdits e = edits;
        out.put("editable", e != null);
        out.put("reload", e == null ? RunEdits.Reload.NONE : e.reloads());
        out.put("whatIfRefusal", e == null ? null : e.whatIfRefusal());
        out.put("whatIfs", List.copyOf(whatIfs));
        return out;
    }

    /** {@code GET /api/debug}: the state; {@code POST /api/debug?cmd=continue|step|pause|break|delete[&spec=S]}: a command. */
    private void debug(HttpExchange ex) throws IOException {
        Debugger d = debugger;
        if (ex.getRequestMethod().equals("POST")) {
            if (d == null) {
                send(ex, 409, "text/plain", "this run cannot halt (lockstep runs only)".getBytes(StandardCharsets.UTF_8));
                return;
            }
            String cmd = query(ex).getOrDefault("cmd", ""), spec = query(ex).getOrDefault("spec", "");
            try {
                switch (cmd) {
                    case "continue" -> d.resume();
                    case "step" -> d.step();
                    case "cycle" -> d.stepCycle();
                    case "pause" -> d.pause();
                    case "break" -> d.add(spec);
                    case "delete" -> d.remove(spec);
                    default -> throw new IllegalArgumentException("unknown command '" + cmd + "'");
                }
            } catch (IllegalArgumentException e) {
                send(ex, 400, "text/plain", e.getMessage().getBytes(StandardCharsets.UTF_8));
                return;
            }
        }
        sendJson(ex, debugState());
    }

    /** Lets the page start what-ifs from any instant (and reload plans into a live run). */
    public void edits(RunEdits e) {
        this.edits = e;
    }

    /** {@return the what-ifs started from the page} */
    public List<WhatIfJob> whatIfs() {
        return List.copyOf(whatIfs);
    }

    /**
     * {@code POST /api/whatif?t=MS&seconds=S} with the edited program as the body: starts a
     * what-if on a thread of its own; its history appears as another agent once it has run.
     */
    private void whatIf(HttpExchange ex) throws IOException {
        if (!ex.getRequestMethod().equals("POST")) {
            sendJson(ex, whatIfs());
            return;
        }
        RunEdits e = edits;
        if (e == null) {
            sendText(ex, 409, "this run has no step log to start a what-if from");
            return;
        }
        if (e.whatIfRefusal() != null) {
            sendText(ex, 409, e.whatIfRefusal());
            return;
        }
        long at = time(query(ex).get("t")), seconds = time(query(ex).get("seconds"));
        if (at < 0 || seconds <= 0) {
            sendText(ex, 400, "a what-if needs t (ms, at least 0) and seconds (more than 0)");
            return;
        }
        String program = body(ex);
        var job = new WhatIfJob("what-if " + (whatIfs.size() + 1) + " from " + at / 1000.0 + " s", at, seconds);
        whatIfs.add(job);
        threads.execute(() -> {
            try {
                e.whatIf(job, program);
            } catch (IllegalArgumentException x) {
                job.failed(x.getMessage());
            } catch (Exception x) {
                job.failed(x.toString());
            }
        });
        sendJson(ex, job);
    }

    /**
     * {@code POST /api/reload} with a program as the body: its plans replace the live run's (a
     * lockstep run's at its halt, a real-time run's at the agent's next cycle); the answer says what happened.
     */
    private void reload(HttpExchange ex) throws IOException {
        RunEdits e = edits;
        if (!ex.getRequestMethod().equals("POST") || e == null) {
            sendText(ex, 409, "POST a program to a live run's inspector");
            return;
        }
        try {
            String what = e.reload(body(ex));
            sendJson(ex, Map.of("message", what, "debug", debugState()));
        } catch (IllegalStateException | IllegalArgumentException x) {
            sendText(ex, 409, x.getMessage());
        } catch (Exception x) {
            sendText(ex, 500, x.toString());
        }
    }

    /** {@return the request's body as text (at most 1 MB: an agent program)} */
    private static String body(HttpExchange ex) throws IOException {
        byte[] b = ex.getRequestBody().readNBytes(1 << 20);
        return new String(b, StandardCharsets.UTF_8);
    }

    /** {@return a time given in a query (ms), -1 when missing or not a number} */
    private static long time(String text) {
        try {
            return text == null ? -1 : Long.parseLong(text);
        } catch (NumberFormatException e) {
            return -1;
        }
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
                String debugNow = JSON.writeValueAsString(debugState());
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
                        out.write(("event: frame\ndata: " + JSON.writeValueAsString(push) + "\n\n").getBytes(StandardCharsets.UTF_8));
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

    private static Map<String, String> query(HttpExchange ex) {
        var out = new HashMap<String, String>();
        String q = ex.getRequestURI().getRawQuery();
        if (q != null) {
            for (String pair : q.split("&")) {
                int eq = pair.indexOf('=');
                if (eq > 0) {
                    out.put(URLDecoder.decode(pair.substring(0, eq), StandardCharsets.UTF_8),
                            URLDecoder.decode(pair.substring(eq + 1), StandardCharsets.UTF_8));
                }
            }
        }
        return out;
    }

    private static byte[] resource(String name) throws IOException {
        try (InputStream in = Inspector.class.getResourceAsStream(name)) {
            return in.readAllBytes();
        }
    }

    private static void sendText(HttpExchange ex, int status, String text) throws IOException {
        send(ex, status, "text/plain; charset=utf-8", text.getBytes(StandardCharsets.UTF_8));
    }

    private static void sendJson(HttpExchange ex, Object value) throws IOException {
        send(ex, 200, "application/json; charset=utf-8", JSON.writeValueAsBytes(value));
    }

    private static void send(HttpExchange ex, int status, String type, byte[] body) throws IOException {
        ex.getResponseHeaders().set("Content-Type", type);
        ex.getResponseHeaders().set("Cache-Control", "no-store");
        ex.sendResponseHeaders(status, body.length == 0 ? -1 : body.length);
        try (OutputStream out = ex.getResponseBody()) {
            out.write(body);
        }
    }

    private static String escapeHtml(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
