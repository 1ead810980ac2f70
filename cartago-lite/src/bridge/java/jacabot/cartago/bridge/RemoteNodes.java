package jacabot.cartago.bridge;

import jacabot.cartago.CartagoLogger;
import jacabot.cartago.WorkspaceId;
import jacabot.cartago.remote.RemoteWorkspace;
import jacabot.cartago.remote.WorkspaceSecret;
import jacabot.cartago.remote.WorkspaceServer;
import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The node's network side, as JaCa's environment arguments choose it:
 * {@code CartagoEnvironment("infrastructure")} (optionally {@code port(N)}) makes this node's
 * workspaces reachable from agents of other processes on the loopback address
 * ({@link WorkspaceServer}, port {@value WorkspaceServer#DEFAULT_PORT} unless {@value #PORT_PROPERTY}
 * says otherwise); any node joins remote workspaces with {@code joinRemoteWorkspace}. Both ends prove
 * the secret of {@link WorkspaceSecret#defaultFile()}. There is one protocol: a {@code protocol(...)}
 * argument (CArtAgO's {@code lipermi}, {@code rmi}) is accepted and changes nothing.
 */
final class RemoteNodes {
    static final String PROTOCOL = "default";
    static final String PORT_PROPERTY = "jacabot.cartago.port";
    private static final Pattern PORT_ARG = Pattern.compile("port\\((\\d+)\\)");

    private final CartagoEnvironment node;
    private final WorkspaceServer server;
    private final List<RemoteWorkspace> sessions = new ArrayList<>();
    /** Connects and handshakes off the agents' threads; one at a time, the thread ends when idle. */
    private final ExecutorService connector = new ThreadPoolExecutor(0, 1, 10, TimeUnit.SECONDS,
            new LinkedBlockingQueue<>(), r -> {
                var t = new Thread(r, "remote-workspace-connector");
                t.setDaemon(true);
                return t;
            });

    RemoteNodes(CartagoEnvironment node, List<String> args, PrintStream console) {
        this.node = node;
        WorkspaceServer started = null;
        if (args.contains("infrastructure")) {
            int port = defaultPort();
            for (String a : args) {
                Matcher m = PORT_ARG.matcher(a.replace(" ", ""));
                if (m.matches()) {
                    port = Integer.parseInt(m.group(1));
                }
            }
            try {
                started = WorkspaceServer.start(port, node::workspace, WorkspaceSecret.loadOrCreate(WorkspaceSecret.defaultFile()),
                        CartagoLogger.console(console));
            } catch (IOException e) {
                throw new IllegalArgumentException("CartagoEnvironment(\"infrastructure\"): " + e.getMessage(), e);
            }
        }
        server = started;
    }

    /** {@return the port this node listens on, or -1 when it is not an infrastructure node} */
    int port() {
        return server == null ? -1 : server.port();
    }

    static int defaultPort() {
        return Integer.getInteger(PORT_PROPERTY, WorkspaceServer.DEFAULT_PORT);
    }

    /** Joins {@code name} at {@code address} ({@code host[:port]}); the reply binds argument {@code outputIndex}. */
    void join(AgentSession session, String name, String address, String protocol, int outputIndex,
            CartagoEnvironment.Reply reply) {
        String host = address;
        int port = defaultPort();
        int colon = address.lastIndexOf(':');
        if (colon > 0 && address.indexOf(':') == colon) {
            try {
                port = Integer.parseInt(address.substring(colon + 1));
                host = address.substring(0, colon);
            } catch (NumberFormatException e) {
                reply.fail("bad address " + address + " (host or host:port)", "bad_argument", List.of(2));
                return;
            }
        }
        String h = host;
        int p = port;
        WorkspaceId id = new WorkspaceId(name, h + ":" + p);
        connector.execute(() -> {
            RemoteWorkspace w;
            try {
                // a lost node leaves the agent as a quit would (its percepts there are gone already)
                w = RemoteWorkspace.join(h, p, name, session.agent(), session.observer(),
                        WorkspaceSecret.loadOrCreate(WorkspaceSecret.defaultFile()),
                        () -> session.find(id).ifPresent(session::quitted));
            } catch (IOException | RuntimeException e) {
                reply.fail("cannot join workspace " + name + " at " + h + ":" + p + ": " + e.getMessage(),
                        "join_failed", List.of(name, address));
                return;
            }
            synchronized (sessions) {
                sessions.add(w);
            }
            session.joined(new JoinedWorkspace.Remote(w, id));
            reply.succeed(Map.of(outputIndex, id));
        });
    }

    void close() {
        connector.shutdownNow();
        synchronized (sessions) {
            sessions.forEach(RemoteWorkspace::close);
        }
        if (server != null) {
            server.close();
        }
    }
}
