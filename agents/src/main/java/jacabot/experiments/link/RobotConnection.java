package jacabot.experiments.link;

import jacabot.robot.link.AuthenticationException;
import jacabot.robot.link.Command;
import jacabot.robot.link.CommandWriter;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.LockstepSpin;
import jacabot.robot.link.MemoryLink;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.ProtocolException;
import jacabot.robot.link.ReadingCheck;
import jacabot.robot.link.SensorDataReader;
import jacabot.robot.link.SensorInfoFilter;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketAddress;
import java.util.List;

/**
 * One accepted controller: its handshake (which proves it holds the link secret), the thread that
 * reads its sensor data stream, and the command stream to it. Nothing read is trusted: a batch with a
 * malformed reading is dropped and reported ({@link ReadingCheck}); after {@code maxBadFrames} of them
 * the connection is closed. Every way the connection can end is reported once, with its reason.
 * Over an in-process link ({@link #attachInMemory}) the same checks run on the controller's thread,
 * with neither handshake nor reading thread; over a socket in one process, a lockstep connection's
 * stream is lent to the controller's thread between the handshake and the end ({@link CallerTurn}).
 */
final class RobotConnection {
    /** Null for an in-process link. */
    private final Socket socket;
    /** The controller's end of the socket; null for an in-process link. */
    private final SocketAddress remote;
    private final CallerTurn turn;
    /** Null for a socket. */
    private final MemoryLink memory;
    private volatile boolean memoryClosed;
    private ReadingCheck check;
    private final ConnectionOwner owner;
    private final SensorInfoFilter.Limits limits;
    private final LinkCosts costs;
    private final LinkSecret secret;
    private final int maxBadFrames;
    private final long startedNanos = System.nanoTime();
    private volatile Protocol.Hello hello;
    private volatile CommandWriter commands;
    private volatile SensorDataReader reader;
    private volatile String closeReason;
    private volatile boolean handshakeDone;
    private int badFrames;

    RobotConnection(Socket socket, ConnectionOwner owner, LinkConfig config, LinkCosts costs, CallerTurn turn) {
        this(socket, null, owner, config, costs, turn);
    }

    private RobotConnection(Socket socket, MemoryLink memory, ConnectionOwner owner, LinkConfig config, LinkCosts costs,
            CallerTurn turn) {
        this.socket = socket;
        this.remote = socket == null ? null : socket.getRemoteSocketAddress();
        this.turn = turn;
        this.memory = memory;
        this.owner = owner;
        this.limits = config.limits();
        this.costs = costs;
        this.secret = socket == null ? null : config.secret(); // an in-process link has no handshake
        this.maxBadFrames = config.guards().maxBadFrames();
    }

    /**
     * The controller of an in-process link, attached at once: no handshake (nothing but this
     * process reaches the link), and its frames are read on the controller's writing thread.
     */
    static MemoryLink.Reader attachInMemory(MemoryLink memory, Protocol.Hello hello, ConnectionOwner owner, LinkConfig config,
            LinkCosts costs) throws IOException {
        RobotConnection c = new RobotConnection(null, memory, owner, config, costs, null);
        var r = new SensorDataReader(memory.middlewareIn(), c.limits); // the stream header is there already
        r.measure(costs);
        c.reader = r;
        c.check = new ReadingCheck(hello.sensors());
        c.hello = hello;
        c.handshakeDone = true;
        owner.attached(c);
        return new MemoryLink.Reader() {
            @Override
            public void read(long frames) {
                c.readInMemory(frames);
            }

            @Override
            public void closed(String reason) {
                c.endInMemory(reason);
            }
        };
    }

    private void readInMemory(long frames) {
        try {
            for (long i = 0; i < frames && !memoryClosed; i++) {
                String end = handle(reader.read());
                if (end != null) {
                    memory.close(end);
                }
            }
        } catch (IOException e) {
            memory.close(e instanceof ProtocolException ? e.getMessage() : "link failed: " + e.getMessage());
        }
    }

    /** Reports the end of an in-process connection once, with the first reason given. */
    private void endInMemory(String reason) {
        String r;
        synchronized (this) {
            if (memoryClosed) {
                return;
            }
            memoryClosed = true;
            if (closeReason == null) {
                closeReason = reason;
            }
            r = closeReason;
        }
        owner.detached(this, r);
    }

    void start() {
        Thread t = new Thread(this::run, "middleware-reader-" + socket.getPort());
        t.setDaemon(true);
        t.start();
    }

    Protocol.Hello hello() {
        return hello;
    }

    SocketAddress remote() {
        return remote;
    }

    SensorDataReader reader() {
        return reader;
    }

    boolean handshakeDone() {
        return handshakeDone;
    }

    long startedNanos() {
        return startedNanos;
    }

    /** {@return when the frame being read began, 0 between frames or before the stream} */
    long frameStartNanos() {
        SensorDataReader r = reader;
        return r == null ? 0 : r.frameStartNanos();
    }

    boolean isClosed() {
        return memory != null ? memoryClosed : socket.isClosed();
    }

    void send(int seq, long sentMicros, Command c) throws IOException {
        if (memory != null) {
            memory.fromMiddleware(w -> w.write(seq, sentMicros, c));
            return;
        }
        CommandWriter w = commands;
        if (w == null) {
            throw new IOException("not connected");
        }
        w.write(seq, sentMicros, c);
    }

    /** Writes several commands with one flush. */
    void send(int[] seqs, long sentMicros, List<Command> frames) throws IOException {
        if (memory != null) {
            memory.fromMiddleware(w -> w.writeAll(seqs, sentMicros, frames));
            return;
        }
        CommandWriter w = commands;
        if (w == null) {
            throw new IOException("not connected");
        }
        w.writeAll(seqs, sentMicros, frames);
    }

    /** Closes the socket; the reader thread then reports {@code reason} (the first reason wins). */
    void close(String reason) {
        synchronized (this) {
            if (closeReason == null) {
                closeReason = reason;
            }
        }
        if (memory != null) {
            memory.close(reason); // both ends hear it; this one reports its end then
            return;
        }
        try {
            socket.close();
        } catch (IOException e) {
            // closed anyway
        }
        if (turn != null) {
            turn.giveBack(this); // its thread reads the end and reports it
        }
    }

    private void run() {
        String reason;
        boolean attached = false;
        boolean authentication = false;
        try {
            socket.setTcpNoDelay(true);
            var out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
            // the owner's watchdog closes a connection whose handshake takes too long
            Protocol.Hello h = Handshake.asMiddleware(new DataInputStream(socket.getInputStream()), out, secret);
            hello = h;
            commands = new CommandWriter(out);
            handshakeDone = true;
            owner.attached(this);
            attached = true;
            check = new ReadingCheck(h.sensors());
            var r = new SensorDataReader(socket.getInputStream(), limits);
            r.measure(costs);
            reader = r;
            reason = h.lockstep() && turn != null ? turn.lend(this) : null; // the controller's thread reads meanwhile
            if (h.lockstep()) {
                r.spinWith(new LockstepSpin()); // the controller waits for our answer, and we for its next step
            }
            while (reason == null) {
                reason = handle(r.read());
            }
        } catch (AuthenticationException e) {
            reason = e.getMessage();
            authentication = true;
        } catch (IOException | RuntimeException e) {
            reason = endReason(e);
        }
        synchronized (this) {
            if (closeReason != null) {
                reason = closeReason;
            } else {
                closeReason = reason;
            }
        }
        close(reason);
        if (attached) {
            owner.detached(this, reason);
        } else {
            owner.refused(this, reason + " (from " + socket.getRemoteSocketAddress() + ")", authentication);
        }
    }

    /** {@return why reading the stream ended with {@code e}} */
    static String endReason(Exception e) {
        if (e instanceof ProtocolException) {
            return e.getMessage();
        }
        return e instanceof IOException ? "link dropped: " + e.getMessage() : "link failed: " + e;
    }

    /** Checks a frame and passes it on; {@return why the connection ends with it, or null} */
    String handle(Uplink frame) {
        if (frame == null) {
            return "the controller closed the connection";
        }
        String bad = frame instanceof Uplink.Batch ? check.problem((Uplink.Batch) frame) : null;
        if (bad == null) {
            try {
                owner.frame(this, frame);
            } catch (RuntimeException e) {
                bad = "handling it failed: " + e; // the reading thread goes on with the next frame
            }
        }
        if (bad != null) {
            owner.badFrame(this, bad);
            if (++badFrames > maxBadFrames) {
                return "more than " + maxBadFrames + " bad frames; the last: " + bad;
            }
        }
        if (frame instanceof Uplink.Bye) {
            return "the controller said goodbye: " + ((Uplink.Bye) frame).reason();
        }
        return null;
    }
}
