package jacabot.cartago.remote;

import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserver;
import jacabot.cartago.OpCallback;
import jacabot.cartago.OpFeedbackParam;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.OpTarget;
import jacabot.cartago.PropertySnapshot;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.UnaryOperator;

/**
 * One agent's session in a workspace of another process ({@link WorkspaceServer}): operations go
 * there, and what the agent perceives there comes back to its observer, on this session's reader
 * thread. Artifact ids of that workspace carry its full name, {@code name@host:port}. When the
 * connection is lost (not quit), operations under way fail with {@code workspace_closed}, the
 * observer hears that every focus there ended, and the {@code lost} callback runs. After a
 * {@link #quit} too the observer has heard the end of every focus there.
 */
public final class RemoteWorkspace implements AutoCloseable {
    private static final int CONNECT_TIMEOUT_MS = 5000;

    private final Socket socket;
    private final DataOutputStream out;
    private final String remoteName;
    private final String fullName;
    private final Map<Integer, Pending> pending = new ConcurrentHashMap<>();
    private final AtomicInteger opIds = new AtomicInteger();
    private volatile boolean closed;
    private volatile boolean quitting;
    /** Set by {@link #close}: the observer is told nothing more. */
    private volatile boolean closing;
    private Thread reader;
    /** What the agent focuses there, as the events told (read on loss, to end those focuses). */
    private final Map<ArtifactId, List<PropertySnapshot>> focused = new LinkedHashMap<>();

    private record Pending(OpCallback callback, Object[] args) {
    }

    private RemoteWorkspace(Socket socket, DataOutputStream out, String remoteName, String fullName) {
        this.socket = socket;
        this.out = out;
        this.remoteName = remoteName;
        this.fullName = fullName;
    }

    /**
     * Connects to the node at {@code host:port}, proves the secret and joins {@code workspace} as
     * {@code agent}.
     *
     * @throws IOException when the node cannot be reached, fails the handshake or refuses the join
     */
    public static RemoteWorkspace join(String host, int port, String workspace, String agent, ArtifactObserver observer,
            WorkspaceSecret secret) throws IOException {
        return join(host, port, workspace, agent, observer, secret, () -> { });
    }

    /** As {@link #join(String, int, String, String, ArtifactObserver, WorkspaceSecret)}, told when the connection is lost. */
    public static RemoteWorkspace join(String host, int port, String workspace, String agent, ArtifactObserver observer,
            WorkspaceSecret secret, Runnable lost) throws IOException {
        var socket = new Socket();
        try {
            socket.connect(new InetSocketAddress(host, port), CONNECT_TIMEOUT_MS);
            socket.setTcpNoDelay(true);
            socket.setSoTimeout(CONNECT_TIMEOUT_MS);
            var in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
            var out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
            RemoteHandshake.asClient(in, out, secret);
            out.writeByte(Frames.JOIN);
            Wire.writeString(out, workspace);
            Wire.writeString(out, agent);
            out.flush();
            if (in.readUnsignedByte() != Frames.JOINED) {
                throw new IOException("the node did not answer the join");
            }
            boolean ok = in.readBoolean();
            String message = Wire.readString(in);
            if (!ok) {
                throw new IOException(message);
            }
            socket.setSoTimeout(0);
            var w = new RemoteWorkspace(socket, out, workspace, workspace + "@" + host + ":" + port);
            w.reader = new Thread(() -> w.readLoop(in, observer, lost), "remote-workspace-" + w.fullName);
            w.reader.setDaemon(true);
            w.reader.start();
            return w;
        } catch (IOException e) {
            socket.close();
            throw e;
        }
    }

    /** {@return {@code name@host:port}, the workspace of this session's artifact ids} */
    public String fullName() {
        return fullName;
    }

    /** Names as the node calls them: our full name is its plain one. */
    private String toNode(String workspace) {
        return workspace.equals(fullName) ? remoteName : workspace;
    }

    private String fromNode(String workspace) {
        return workspace.equals(remoteName) ? fullName : workspace;
    }

    /**
     * Runs an operation there. An argument of a shape that may not cross fails it at once with
     * {@code bad_argument(Index)}, nothing sent.
     */
    public void execOp(OpTarget target, String operation, Object[] args, OpCallback callback) {
        for (int i = 0; i < args.length; i++) {
            try {
                Wire.check(args[i]);
            } catch (Wire.NotTransferable e) {
                callback.completed(new OpOutcome.Failure("argument " + (i + 1) + ": " + e.getMessage(), "bad_argument",
                        List.of(i + 1)));
                return;
            }
        }
        int id = opIds.incrementAndGet();
        // the whole frame first, so that a value the wire refuses (a string over 1 MiB) sends nothing
        var bytes = new ByteArrayOutputStream();
        try {
            var f = new DataOutputStream(bytes);
            f.writeByte(Frames.EXEC);
            f.writeInt(id);
            if (target.isAny()) {
                f.writeByte(Frames.TARGET_ANY);
            } else if (target.id() != null) {
                f.writeByte(Frames.TARGET_ID);
                Wire.write(f, target.id(), this::toNode);
            } else {
                f.writeByte(Frames.TARGET_NAME);
                Wire.writeString(f, target.name());
            }
            Wire.writeString(f, operation);
            f.writeInt(args.length);
            for (Object a : args) {
                Wire.write(f, a, this::toNode);
            }
        } catch (IOException e) {
            callback.completed(new OpOutcome.Failure(operation + ": " + e.getMessage(), "bad_argument", List.of()));
            return;
        }
        pending.put(id, new Pending(callback, args));
        try {
            synchronized (out) {
                if (closed) {
                    throw new IOException("closed");
                }
                bytes.writeTo(out);
                out.flush();
            }
        } catch (IOException e) {
            Pending p = pending.remove(id);
            if (p != null) {
                p.callback().completed(lost());
            }
        }
    }

    private static OpOutcome.Failure lost() {
        return new OpOutcome.Failure("the connection to the remote workspace is lost", "workspace_closed", List.of());
    }

    private void readLoop(DataInputStream in, ArtifactObserver observer, Runnable lost) {
        UnaryOperator<String> rename = this::fromNode;
        try {
            while (true) {
                int type = in.readUnsignedByte();
                if (type == Frames.OUTCOME) {
                    outcome(in, rename);
                } else if (type == Frames.EVENT) {
                    event(in, rename, observer, focused);
                } else {
                    throw new IOException("unknown frame " + type);
                }
            }
        } catch (IOException ended) {
            boolean unexpected = !quitting && !closing;
            closeSocket();
            for (Integer id : new ArrayList<>(pending.keySet())) {
                Pending p = pending.remove(id);
                if (p != null) {
                    p.callback().completed(lost());
                }
            }
            if (!closing) {
                // lost, or quit: the focus there is over either way. A node may close the connection
                // before its own ENDED frames leave (it stops as the agent leaves): those end here.
                focused.forEach((id, props) -> observer.focusEnded(id, props, false));
                focused.clear();
            }
            if (unexpected) {
                lost.run();
            }
        }
    }

    private void outcome(DataInputStream in, UnaryOperator<String> rename) throws IOException {
        int id = in.readInt();
        OpOutcome outcome;
        if (in.readBoolean()) {
            int n = in.readInt();
            if (n < 0 || n > 255) {
                throw new IOException(n + " outputs");
            }
            Map<Integer, Object> outputs = new HashMap<>();
            for (int i = 0; i < n; i++) {
                outputs.put(in.readInt(), Wire.read(in, rename));
            }
            outcome = new OpOutcome.Success(outputs);
        } else {
            String message = Wire.readString(in);
            Object functor = Wire.read(in, rename);
            Object args = Wire.read(in, rename);
            if (functor != null && !(functor instanceof String) || !(args instanceof List<?>)) {
                throw new IOException("a malformed failure");
            }
            outcome = new OpOutcome.Failure(message, (String) functor, new ArrayList<>((List<?>) args));
        }
        Pending p = pending.remove(id);
        if (p == null) {
            return;   // not ours: ignore
        }
        if (outcome instanceof OpOutcome.Success s) {
            // the markers given to the operation read as they do locally
            s.outputs().forEach((i, v) -> {
                if (i >= 0 && i < p.args().length && p.args()[i] instanceof OpFeedbackParam<?> f) {
                    @SuppressWarnings("unchecked")
                    var param = (OpFeedbackParam<Object>) f;
                    param.set(v);
                }
            });
        }
        p.callback().completed(outcome);
    }

    private static void event(DataInputStream in, UnaryOperator<String> rename, ArtifactObserver observer,
            Map<ArtifactId, List<PropertySnapshot>> focused) throws IOException {
        int kind = in.readUnsignedByte();
        if (!(Wire.read(in, rename) instanceof ArtifactId id)) {
            throw new IOException("an event without its artifact");
        }
        switch (kind) {
            case Frames.FOCUSED -> {
                List<PropertySnapshot> props = Wire.readProperties(in, rename);
                focused.put(id, new ArrayList<>(props));
                observer.focused(id, props);
            }
            case Frames.ADDED -> {
                PropertySnapshot p = Wire.readProperty(in, rename);
                focused.computeIfAbsent(id, k -> new ArrayList<>()).add(p);
                observer.propertyAdded(id, p);
            }
            case Frames.UPDATED -> {
                PropertySnapshot old = Wire.readProperty(in, rename);
                PropertySnapshot now = Wire.readProperty(in, rename);
                List<PropertySnapshot> props = focused.get(id);
                if (props != null && props.indexOf(old) >= 0) {
                    props.set(props.indexOf(old), now);
                }
                observer.propertyUpdated(id, old, now);
            }
            case Frames.REMOVED -> {
                PropertySnapshot p = Wire.readProperty(in, rename);
                List<PropertySnapshot> props = focused.get(id);
                if (props != null) {
                    props.remove(p);
                }
                observer.propertyRemoved(id, p);
            }
            case Frames.SIGNALLED -> {
                String type = Wire.readString(in);
                Object args = Wire.read(in, rename);
                if (!(args instanceof List<?> l)) {
                    throw new IOException("a signal without its list of values");
                }
                observer.signalled(id, type, new ArrayList<>(l));
            }
            case Frames.ENDED -> {
                List<PropertySnapshot> props = Wire.readProperties(in, rename);
                focused.remove(id);
                observer.focusEnded(id, props, in.readBoolean());
            }
            default -> throw new IOException("unknown event kind " + kind);
        }
    }

    /**
     * Leaves the workspace: the node ends the agent's focus, disposes its body and closes the
     * connection (waited for up to 2 s). When this returns the observer has heard the end of every
     * focus there, from the node or, for those the node did not tell in time, from here.
     */
    public void quit() {
        quitting = true;
        try {
            synchronized (out) {
                if (!closed) {
                    out.writeByte(Frames.QUIT);
                    out.flush();
                }
            }
            if (Thread.currentThread() != reader) {
                reader.join(2000);
            }
        } catch (IOException ignored) {
            // closing anyway
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        closeSocket();
        if (Thread.currentThread() != reader) {
            try {
                reader.join(10_000);   // the socket is closed: the reader ends at once, telling the observer
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Closes the connection without telling the observer or the {@code lost} callback (the node is told as by a quit). */
    @Override
    public void close() {
        closing = true;
        closeSocket();
    }

    private void closeSocket() {
        closed = true;
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}
