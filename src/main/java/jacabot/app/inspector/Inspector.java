package jacabot.app.inspector;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.sun.net.httpserver.HttpExchange;
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
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

/**
 * The mind inspector: a web page on loopback showing each agent's beliefs, events, intentions,
 * plan library and deliberation trace, and for a robot its body and the middleware's commands,
 * as Jason's web mind inspector does. Served by the JDK's {@code com.sun.net.httpserver}; the page
 * follows the run through server-sent events ({@code /api/stream}) and reads the past through
 * {@code /api/state?agent=A&frame=K}. The agents' threads only put immutable frames into each
 * {@link MindHistory}; the server's threads only read them.
 */
public final class Inspector implements AutoCloseable {
    /** The port tried first (Jason's inspector uses 3272); when taken, any free port. */
    public static final int DEFAULT_PORT = 3273;
    /** Frames kept per agent. */
    public static final int HISTORY = 2000;
    /** At most this many pushes per second per page (the run may be much faster than real time). */
    static final int PUSHES_PER_SECOND = 5;

    private static final ObjectMapper JSON = new ObjectMapper();

    private final HttpServer server;
    private final ExecutorService threads;
    private final Map<String, MindHistory> agents = new LinkedHashMap<>();
    private volatile Path plotDir;
    private volatile String title = "jacabot";
    private volatile boolean closed;

    private Inspector(HttpServer server) {
        this.server = server;
        this.threads = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "inspector-http");
            t.setDaemon(true);
            return t;
        });
        server.setExecutor(threads);
        server.createContext("/", this::page);
        server.createContext("/api/agents", ex -> sendJson(ex, agentNames()));
        server.createContext("/api/state", this::state);
        server.createContext("/api/history", this::history);
        server.createContext("/api/plans", ex -> sendJson(ex, historyOf(ex).map(MindHistory::plans).orElse(List.of())));
        server.createContext("/api/stream", this::stream);
        server.createContext("/plots/", this::plot);
        server.start();
    }

    /**
     * Starts an inspector on loopback.
     *
     * @param port the port, or 0 for {@link #DEFAULT_PORT} if free and any free port otherwise
     */
    public static Inspector start(int port) throws IOException {
        InetAddress loopback = InetAddress.getLoopbackAddress();
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

    /** {@return the page's address} */
    public URI uri() {
        return URI.create("http://127.0.0.1:" + server.getAddress().getPort() + "/");
    }

    /** Adds an agent; its frames go into the returned history. */
    public synchronized MindHistory add(String agent) {
        return agents.computeIfAbsent(agent, a -> new MindHistory(a, HISTORY));
    }

    /** Serves the run's plots (PNG files of this folder) under {@code /plots/}. */
    public void showPlots(Path dir) {
        this.plotDir = dir;
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

    // ---- handlers ---------------------------------------------------------------------------------

    private synchronized List<String> agentNames() {
        return new ArrayList<>(agents.keySet());
    }

    private synchronized java.util.Optional<MindHistory> historyOf(HttpExchange ex) {
        String name = query(ex).get("agent");
        if (name == null && !agents.isEmpty()) {
            name = agents.keySet().iterator().next();
        }
        return java.util.Optional.ofNullable(name == null ? null : agents.get(name));
    }

    private void page(HttpExchange ex) throws IOException {
        if (!ex.getRequestURI().getPath().equals("/")) {
            send(ex, 404, "text/plain", "not found".getBytes(StandardCharsets.UTF_8));
            return;
        }
        try (InputStream in = Inspector.class.getResourceAsStream("inspector.html")) {
            String html = new String(in.readAllBytes(), StandardCharsets.UTF_8).replace("{{title}}", escapeHtml(title));
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
        MindHistory.Frame f;
        try {
            f = at == null ? h.get().latest() : h.get().frame(Long.parseLong(at));
        } catch (NumberFormatException e) {
            send(ex, 400, "text/plain", ("bad frame '" + at + "'").getBytes(StandardCharsets.UTF_8));
            return;
        }
        sendJson(ex, f);
    }

    private void history(HttpExchange ex) throws IOException {
        var h = historyOf(ex);
        if (h.isEmpty()) {
            send(ex, 404, "text/plain", "no such agent".getBytes(StandardCharsets.UTF_8));
            return;
        }
        var out = new HashMap<String, Object>();
        out.put("timeline", h.get().timeline());
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
            while (!closed) {
                boolean sent = false;
                for (String name : agentNames()) {
                    MindHistory h;
                    synchronized (this) {
                        h = agents.get(name);
                    }
                    long v = h.version();
                    if (seen.getOrDefault(name, -1L) != v && h.latest() != null) {
                        seen.put(name, v);
                        out.write(("event: frame\ndata: " + JSON.writeValueAsString(Map.of("agent", name, "frame", h.latest()))
                                + "\n\n").getBytes(StandardCharsets.UTF_8));
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
                        first.awaitChange(seen.getOrDefault(names.get(0), -1L), 1000);
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
