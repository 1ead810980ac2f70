package jacabot.experiments.link;

import jacabot.robot.link.LinkCosts;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Collection;
import java.util.Collections;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The listening end (thesis §2.3: the artifact "creates a new ServerSocket on a well-known port,
 * waits for a connection request from the robot platform"): binds the server socket, plain on
 * loopback or TLS ({@link LinkConfig#tls()}), and accepts controllers on its own thread. Each
 * accepted socket becomes a {@link RobotConnection} that shakes hands on its own thread, unless the
 * {@link HandshakeGuard} closes it unheard. It keeps the connections not closed yet, for the
 * {@link ConnectionWatchdog}.
 */
final class LinkListener {
    private final ServerSocket server;
    private final LinkConfig config;
    private final HandshakeGuard guard;
    private final ConnectionOwner owner;
    private final LinkCosts costs;
    private final CallerTurn turn;
    /** Connections not yet closed, shaking hands or attached. */
    private final Set<RobotConnection> live = ConcurrentHashMap.newKeySet();
    private final Thread acceptor = new Thread(this::acceptLoop, "middleware-acceptor");
    private volatile boolean closed;

    LinkListener(ServerSocket server, LinkConfig config, HandshakeGuard guard, ConnectionOwner owner,
            LinkCosts costs, CallerTurn turn) {
        this.server = server;
        this.config = config;
        this.guard = guard;
        this.owner = owner;
        this.costs = costs;
        this.turn = turn;
        acceptor.setDaemon(true);
    }

    /**
     * Binds the configured address and port; accepting starts with {@link #start}.
     *
     * @throws IOException when the address cannot be bound (e.g. the port is taken)
     */
    static ServerSocket bind(LinkConfig config) throws IOException {
        ServerSocket server = config.tls() == null ? new ServerSocket()
                : config.tls().getServerSocketFactory().createServerSocket();
        if (config.tls() == null && !config.bindAddress().isLoopbackAddress()) {
            config.log().accept("warning: listening on " + config.bindAddress().getHostAddress()
                    + " without TLS: the link is authenticated but anyone on the path can read it");
        }
        try {
            server.setReuseAddress(true);
            server.bind(new InetSocketAddress(config.bindAddress(), config.port()));
        } catch (IOException e) {
            server.close();
            throw new IOException("cannot listen on " + config.bindAddress().getHostAddress() + ":" + config.port()
                    + ": " + e.getMessage(), e);
        }
        return server;
    }

    /** Starts accepting; each connection reports to the owner. */
    void start() {
        acceptor.start();
    }

    int port() {
        return server.getLocalPort();
    }

    /** {@return the connections not closed yet (a live view)} */
    Collection<RobotConnection> live() {
        return Collections.unmodifiableSet(live);
    }

    /** The connection ended or was refused. */
    void forget(RobotConnection c) {
        live.remove(c);
    }

    /** Stops accepting: the server socket closes, the port is free again. */
    void stopAccepting() {
        closed = true;
        try {
            server.close();
        } catch (IOException e) {
            // closing anyway
        }
    }

    /** Closes every connection not closed yet, with {@code reason}. */
    void closeConnections(String reason) {
        for (RobotConnection c : live) {
            c.close(reason);
        }
        acceptor.interrupt();
    }

    private void acceptLoop() {
        while (!closed) {
            try {
                Socket s = server.accept();
                String busy = guard.refuseAtOnce(() -> live.stream().filter(c -> !c.handshakeDone()).count());
                if (busy != null) {
                    s.close(); // not even a thread for it
                    continue;
                }
                RobotConnection c = new RobotConnection(s, owner, config, costs, turn);
                live.add(c);
                c.start();
            } catch (IOException e) {
                if (!closed) {
                    config.log().accept("accept failed: " + e.getMessage());
                }
            }
        }
    }
}
