package jacabot.cartago.remote;

import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserver;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.OpTarget;
import jacabot.cartago.PropertySnapshot;
import jacabot.cartago.Workspace;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.function.UnaryOperator;

/**
 * Makes a node's workspaces reachable from agents of other processes (CArtAgO's infrastructure
 * service): each connection, once it has proved the {@link WorkspaceSecret}, is one agent in one
 * workspace. It listens on the loopback address only. At most {@value #MAX_SESSIONS} sessions at
 * once; each has a reader thread and a writer thread (events are queued, as observers must not
 * block; a peer that falls {@value #QUEUE} frames behind is dropped). A session that ends, however
 * it ends, leaves its workspace: its focus ends and its body is disposed.
 */
public final class WorkspaceServer implements AutoCloseable {
    /** CArtAgO's default port. */
    public static final int DEFAULT_PORT = 20100;
    static final int MAX_SESSIONS = 32;
    static final int QUEUE = 10_000;
    private static final int HANDSHAKE_TIMEOUT_MS = 5000;

    private final ServerSocket socket;
    private final Function<String, Optional<Workspace>> workspaces;
    private final WorkspaceSecret secret;
    private final CartagoLogger logger;
    private final Semaphore slots = new Semaphore(MAX_SESSIONS);
    private final Set<Socket> open = ConcurrentHashMap.newKeySet();
    private volatile boolean closed;

    private WorkspaceServer(ServerSocket socket, Function<String, Optional<Workspace>> workspaces,
            WorkspaceSecret secret, CartagoLogger logger) {
        this.socket = socket;
        this.workspaces = workspaces;
        this.secret = secret;
        this.logger = logger;
    }

    /**
     * Starts listening on {@code 127.0.0.1:port} ({@code port} 0: one the system picks).
     *
     * @throws IOException when the port is taken
     */
    public static WorkspaceServer start(int port, Function<String, Optional<Workspace>> workspaces,
            WorkspaceSecret secret, CartagoLogger logger) throws IOException {
        var s = new ServerSocket();
        s.setReuseAddress(true);
        try {
            s.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot listen on " + InetAddress.getLoopbackAddress().getHostAddress() + ":" + port
                    + ": " + e.getMessage(), e);
        }
        var server = new WorkspaceServer(s, workspaces, secret, logger);
        var t = new Thread(server::acceptLoop, "workspace-node-" + s.getLocalPort());
        t.setDaemon(true);
        t.start();
        return server;
    }

    public int port() {
        return socket.getLocalPort();
    }

    private void acceptLoop() {
        while (!closed) {
            Socket c;
            try {
                c = socket.accept();
            } catch (IOException e) {
                if (!closed) {
                    logger.warning("node", "accepting a remote agent failed: " + e.getMessage(), null);
                }
                return;
            }
            if (!slots.tryAcquire()) {
                logger.warning("node", "refused a remote agent: " + MAX_SESSIONS + " sessions already", null);
                closeQuietly(c);
                continue;
            }
            open.add(c);
            var t = new Thread(() -> {
                try {
                    serve(c);
                } finally {
                    open.remove(c);
                    closeQuietly(c);
                    slots.release();
                }
            }, "workspace-session-" + c.getPort());
            t.setDaemon(true);
            t.start();
        }
    }

    private void serve(Socket c) {
        Session session = null;
        try {
            c.setTcpNoDelay(true);
            c.setSoTimeout(HANDSHAKE_TIMEOUT_MS);
            var in = new DataInputStream(new BufferedInputStream(c.getInputStream()));
            var out = new DataOutputStream(new BufferedOutputStream(c.getOutputStream()));
            RemoteHandshake.asNode(in, out, secret);
            if (in.readUnsignedByte() != Frames.JOIN) {
                throw new IOException("a session must start by joining a workspace");
            }
            String wsp = Wire.readString(in);
            String agent = Wire.readString(in);
            c.setSoTimeout(0);
            Optional<Workspace> w = workspaces.apply(wsp);
            if (w.isEmpty()) {
                joined(out, false, "no workspace " + wsp + " on this node");
                return;
            }
            session = new Session(c, out, w.get());
            try {
                session.agent = w.get().join(agent, session);
            } catch (IllegalArgumentException | IllegalStateException e) {
                joined(out, false, e.getMessage());
                return;
            }
            joined(out, true, "joined " + wsp);
            session.startWriter();
            session.readLoop(in);
        } catch (EOFException | SocketException ended) {
            // the peer went away
        } catch (IOException e) {
            if (!closed) {
                logger.warning("node", "remote session from port " + c.getPort() + " ended: " + e.getMessage(), null);
            }
        } finally {
            if (session != null) {
                session.end();
            }
        }
    }

    private static void joined(DataOutputStream out, boolean ok, String message) throws IOException {
        out.writeByte(Frames.JOINED);
        out.writeBoolean(ok);
        Wire.writeString(out, message);
        out.flush();
    }

    /** One remote agent in one workspace; its observer queues event frames for the writer. */
    private final class Session implements ArtifactObserver {
        private final Socket socket;
        private final DataOutputStream out;
        private final Workspace workspace;
        private final BlockingQueue<byte[]> outbox = new ArrayBlockingQueue<>(QUEUE);
        private volatile AgentId agent;
        private volatile boolean ended;
        private Thread writer;

        Session(Socket socket, DataOutputStream out, Workspace workspace) {
            this.socket = socket;
            this.out = out;
            this.workspace = workspace;
        }

        void startWriter() {
            writer = new Thread(() -> {
                try {
                    while (true) {
                        byte[] frame = outbox.take();
                        if (frame.length == 0) {
                            out.flush();
                            return;
                        }
                        out.write(frame);
                        if (outbox.isEmpty()) {
                            out.flush();
                        }
                    }
                } catch (IOException | InterruptedException e) {
                    closeQuietly(socket);
                }
            }, "workspace-writer-" + socket.getPort());
            writer.setDaemon(true);
            writer.start();
        }

        void readLoop(DataInputStream in) throws IOException {
            while (true) {
                int type = in.readUnsignedByte();
                if (type == Frames.QUIT) {
                    return;
                }
                if (type != Frames.EXEC) {
                    throw new IOException("unknown frame " + type);
                }
                int opId = in.readInt();
                int kind = in.readUnsignedByte();
                OpTarget target = switch (kind) {
                    case Frames.TARGET_ANY -> OpTarget.any();
                    case Frames.TARGET_ID -> {
                        if (!(Wire.read(in, UnaryOperator.identity()) instanceof ArtifactId id)) {
                            throw new IOException("an operation target that is not an artifact id");
                        }
                        yield OpTarget.id(id);
                    }
                    case Frames.TARGET_NAME -> OpTarget.name(Wire.readString(in));
                    default -> throw new IOException("unknown target kind " + kind);
                };
                String op = Wire.readString(in);
                int argc = in.readInt();
                if (argc < 0 || argc > 255) {
                    throw new IOException(argc + " arguments");
                }
                Object[] args = new Object[argc];
                for (int i = 0; i < argc; i++) {
                    args[i] = Wire.read(in, UnaryOperator.identity());
                }
                workspace.execOp(agent, target, op, args, outcome -> {
                    byte[] frame = frame(o -> outcome(o, opId, outcome));
                    if (frame == null) {   // e.g. a string over the limit: the agent still gets an answer
                        frame = frame(o -> outcome(o, opId, new OpOutcome.Failure(
                                "the operation's result cannot be sent to a remote agent", "not_transferable", List.of())));
                    }
                    send(frame);
                });
            }
        }

        private void outcome(DataOutputStream o, int opId, OpOutcome outcome) throws IOException {
            o.writeByte(Frames.OUTCOME);
            o.writeInt(opId);
            if (outcome instanceof OpOutcome.Success s) {
                o.writeBoolean(true);
                o.writeInt(s.outputs().size());
                for (var e : s.outputs().entrySet()) {
                    o.writeInt(e.getKey());
                    Wire.write(o, Wire.transferable(e.getValue()), UnaryOperator.identity());
                }
            } else {
                var f = (OpOutcome.Failure) outcome;
                o.writeBoolean(false);
                Wire.writeString(o, f.message());
                Wire.write(o, f.reasonFunctor(), UnaryOperator.identity());
                Wire.write(o, Wire.transferable(f.reasonArgs()), UnaryOperator.identity());
            }
        }

        /** Leaves the workspace, then lets the writer send what that produced (focus ended) and stop. */
        void end() {
            AgentId a = agent;
            if (a != null && !workspace.isClosed()) {
                workspace.leave(a);
            }
            ended = true;
            if (writer != null) {
                try {
                    if (outbox.offer(new byte[0], 1, TimeUnit.SECONDS)) {
                        writer.join(2000);
                    }
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }

        private interface Body {
            void write(DataOutputStream o) throws IOException;
        }

        /** Serialises now, as values may change later (values that may not cross were made text before). */
        private byte[] frame(Body body) {
            var bytes = new ByteArrayOutputStream();
            try {
                body.write(new DataOutputStream(bytes));
            } catch (IOException | Wire.NotTransferable e) {
                logger.warning(workspace.getName(), "not sent to remote agent " + agent + ": " + e.getMessage(), null);
                return null;
            }
            return bytes.toByteArray();
        }

        private void send(byte[] frame) {
            if (frame == null || ended || writer == null) {
                return;
            }
            if (!outbox.offer(frame)) {
                logger.warning(workspace.getName(), "remote agent " + agent + " is " + QUEUE + " frames behind: dropped", null);
                closeQuietly(socket);
            }
        }

        private void event(int kind, ArtifactId id, Body rest) {
            send(frame(o -> {
                o.writeByte(Frames.EVENT);
                o.writeByte(kind);
                Wire.write(o, id, UnaryOperator.identity());
                rest.write(o);
            }));
        }

        @Override
        public void focused(ArtifactId artifact, List<PropertySnapshot> properties) {
            event(Frames.FOCUSED, artifact, o -> Wire.writeProperties(o, properties, UnaryOperator.identity()));
        }

        @Override
        public void propertyAdded(ArtifactId artifact, PropertySnapshot property) {
            event(Frames.ADDED, artifact, o -> Wire.writeProperty(o, property, UnaryOperator.identity()));
        }

        @Override
        public void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue) {
            event(Frames.UPDATED, artifact, o -> {
                Wire.writeProperty(o, oldValue, UnaryOperator.identity());
                Wire.writeProperty(o, newValue, UnaryOperator.identity());
            });
        }

        @Override
        public void propertyRemoved(ArtifactId artifact, PropertySnapshot property) {
            event(Frames.REMOVED, artifact, o -> Wire.writeProperty(o, property, UnaryOperator.identity()));
        }

        @Override
        public void signalled(ArtifactId artifact, String type, List<Object> args) {
            event(Frames.SIGNALLED, artifact, o -> {
                Wire.writeString(o, type);
                Wire.write(o, Wire.transferable(args), UnaryOperator.identity());
            });
        }

        @Override
        public void focusEnded(ArtifactId artifact, List<PropertySnapshot> properties, boolean disposed) {
            event(Frames.ENDED, artifact, o -> {
                Wire.writeProperties(o, properties, UnaryOperator.identity());
                o.writeBoolean(disposed);
            });
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        open.forEach(WorkspaceServer::closeQuietly);
    }
}
