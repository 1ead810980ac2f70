package jacabot.experiments.link;

import jacabot.robot.link.Command;
import jacabot.robot.link.CommandWriter;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.ProtocolException;
import jacabot.robot.link.SensorDataReader;
import jacabot.robot.link.SensorInfoFilter;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.List;

/**
 * One accepted controller: its handshake, the thread that reads its sensor data stream, and the
 * command stream to it. Every way the connection can end is reported once, with its reason.
 */
final class RobotConnection {
    private static final int HANDSHAKE_TIMEOUT_MS = 5000;

    /** What the connection tells the link. */
    interface Owner {
        /** The handshake succeeded: this connection is the robot now. */
        void attached(RobotConnection c);

        void frame(RobotConnection c, Uplink frame);

        /** The handshake failed: the connection never became the robot's. */
        void refused(RobotConnection c, String reason);

        /** The connection ended (reason for the log and {@code Disconnected}). */
        void detached(RobotConnection c, String reason);
    }

    private final Socket socket;
    private final Owner owner;
    private final SensorInfoFilter.Limits limits;
    private final LinkCosts costs;
    private volatile Protocol.Hello hello;
    private volatile CommandWriter commands;
    private volatile String closeReason;

    RobotConnection(Socket socket, Owner owner, SensorInfoFilter.Limits limits, LinkCosts costs) {
        this.socket = socket;
        this.owner = owner;
        this.limits = limits;
        this.costs = costs;
    }

    void start() {
        Thread t = new Thread(this::run, "middleware-reader-" + socket.getPort());
        t.setDaemon(true);
        t.start();
    }

    Protocol.Hello hello() {
        return hello;
    }

    void send(int seq, long sentMicros, Command c) throws IOException {
        CommandWriter w = commands;
        if (w == null) {
            throw new IOException("not connected");
        }
        w.write(seq, sentMicros, c);
    }

    /** Writes several commands with one flush. */
    void send(int[] seqs, long sentMicros, List<Command> frames) throws IOException {
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
        try {
            socket.close();
        } catch (IOException e) {
            // closed anyway
        }
    }

    private void run() {
        String reason;
        boolean attached = false;
        try {
            socket.setTcpNoDelay(true);
            socket.setSoTimeout(HANDSHAKE_TIMEOUT_MS);
            Protocol.Hello h = Protocol.Hello.read(new DataInputStream(socket.getInputStream()));
            var out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
            String mismatch = Protocol.versionMismatch(h.version(), Protocol.VERSION);
            new Protocol.Welcome(Protocol.VERSION, mismatch == null, mismatch == null ? "welcome" : mismatch).write(out);
            if (mismatch != null) {
                throw new ProtocolException(mismatch);
            }
            hello = h;
            commands = new CommandWriter(out);
            socket.setSoTimeout(0);
            owner.attached(this);
            attached = true;
            var reader = new SensorDataReader(socket.getInputStream(), limits);
            reader.measure(costs);
            while (true) {
                Uplink frame = reader.read();
                if (frame == null) {
                    reason = "the controller closed the connection";
                    break;
                }
                owner.frame(this, frame);
                if (frame instanceof Uplink.Bye) {
                    reason = "the controller said goodbye: " + ((Uplink.Bye) frame).reason();
                    break;
                }
            }
        } catch (ProtocolException e) {
            reason = e.getMessage();
        } catch (SocketTimeoutException e) {
            reason = "no handshake from " + socket.getRemoteSocketAddress() + " within " + HANDSHAKE_TIMEOUT_MS + " ms";
        } catch (IOException e) {
            reason = "link dropped: " + e.getMessage();
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
            owner.refused(this, reason + " (from " + socket.getRemoteSocketAddress() + ")");
        }
    }
}
