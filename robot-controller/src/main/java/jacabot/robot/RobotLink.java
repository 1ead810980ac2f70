package jacabot.robot;

import jacabot.robot.link.AuthenticationException;
import jacabot.robot.link.CommandReader;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.LockstepSpin;
import jacabot.robot.link.LockstepTurn;
import jacabot.robot.link.MemoryLink;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.ProtocolException;
import jacabot.robot.link.ReceivedCommand;
import jacabot.robot.link.SensorDataWriter;
import jacabot.robot.link.TurnWatch;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketAddress;
import java.net.SocketTimeoutException;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import javax.net.ssl.SSLSocket;

/**
 * The controller's end of the TCP link, with the thesis' two threads (§2.4): the <b>receiver</b>
 * connects (retrying with back-off, reconnecting after a drop), shakes hands and reads commands
 * into the {@link CommandInbox}; the <b>sender</b> writes the frames the simulation thread queues,
 * so neither a slow agent nor a slow socket ever blocks the other direction or the simulation. In
 * lockstep the simulation waits for the agent at every step anyway, so it writes its frames and
 * reads the answers itself; the receiver then only connects and shakes hands.
 *
 * <p>Over a {@link MemoryLink} (lockstep sweeps) there are neither threads nor socket: the same
 * frames go through memory, and the middleware has read a step, and answered it, when its write returns.
 */
final class RobotLink {
    /** A frame waiting for the sender thread. */
    @FunctionalInterface
    interface Frame {
        void writeTo(SensorDataWriter out) throws IOException;
    }

    private static final int HANDSHAKE_TIMEOUT_MS = 5000;

    private final ControllerConfig config;
    private volatile Protocol.Hello hello;
    private final CommandInbox inbox;
    private final LinkCosts costs;
    private final BlockingQueue<Frame> outbox;
    private final CountDownLatch closed = new CountDownLatch(1);
    private final AtomicLong droppedFrames = new AtomicLong();
    private volatile Socket socket;
    /** This end of the connection in use (what a {@link LockstepTurn} serves), null while none is. */
    private volatile SocketAddress localAddress;
    private volatile SensorDataWriter writer;
    /** Lockstep over TCP: the connection's command stream, read by the simulation thread. */
    private volatile LentReader lent;
    private volatile String lastProblem;
    private Thread receiver, sender;
    /** Null: TCP. */
    private final MemoryLink memory;

    RobotLink(ControllerConfig config, CommandInbox inbox, LinkCosts costs, MemoryLink memory) {
        this.config = config;
        this.inbox = inbox;
        this.costs = costs;
        this.outbox = new ArrayBlockingQueue<>(config.outboxCapacity());
        this.memory = memory;
    }

    /** Starts connecting; {@code hello} declares the robot and its enabled sensors. */
    void start(Protocol.Hello greeting) {
        this.hello = greeting;
        if (memory != null) {
            connectInMemory();
            return;
        }
        receiver = new Thread(this::receiveLoop, "controller-receiver");
        sender = new Thread(this::sendLoop, "controller-sender");
        receiver.setDaemon(true);
        sender.setDaemon(true);
        receiver.start();
        sender.start();
    }

    boolean isConnected() {
        return writer != null;
    }

    /** {@return the last connection problem (refused handshake, dropped link, garbage), or null} */
    String lastProblem() {
        return lastProblem;
    }

    /** {@return frames discarded because the link was down or the sender fell behind} */
    long droppedFrames() {
        return droppedFrames.get();
    }

    /**
     * Queues a frame for the sender. When the queue is full (the middleware reads too slowly) the
     * oldest frame goes: sensor data is polled, only the newest matters.
     */
    void send(Frame frame) {
        if (!isConnected()) {
            droppedFrames.incrementAndGet();
            return;
        }
        if (config.lockstep()) {
            write(frame); // the world waits for the agent anyway: the sender thread would only add a hand-off
            return;
        }
        while (!outbox.offer(frame)) {
            if (outbox.poll() != null) {
                droppedFrames.incrementAndGet();
            }
        }
    }

    /** Says goodbye (best effort), closes the socket and stops both threads. */
    void close(String reason) {
        if (closed.getCount() == 0) {
            return;
        }
        SensorDataWriter w = writer;
        // first, in both kinds of link: the middleware closes the connection on our goodbye, and the
        // receiver that sees that end must find the link closed, not report a drop and reconnect
        closed.countDown();
        if (memory != null) {
            if (w != null) {
                try {
                    memory.fromController(out -> out.writeBye(new Uplink.Bye(reason)));
                } catch (IOException e) {
                    // closed already
                }
            }
            memory.close("the controller stopped: " + reason);
            return;
        }
        if (w != null) {
            try {
                w.writeBye(new Uplink.Bye(reason));
            } catch (IOException e) {
                // the link is going anyway
            }
        }
        closeSocket();
        sender.interrupt();
        receiver.interrupt();
        try {
            sender.join(2000);
            receiver.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private boolean isClosed() {
        return closed.getCount() == 0;
    }

    private void sendLoop() {
        try {
            while (!isClosed()) {
                write(outbox.take());
            }
        } catch (InterruptedException e) {
            // closing
        }
    }

    private void write(Frame f) {
        SensorDataWriter w = writer;
        if (w == null) {
            droppedFrames.incrementAndGet();
            return;
        }
        try {
            if (memory != null) {
                memory.fromController(f::writeTo); // the middleware reads the frames before this returns
            } else {
                f.writeTo(w);
            }
        } catch (IOException e) {
            // The receiver notices the broken socket too and reconnects; drop this frame.
            droppedFrames.incrementAndGet();
            closeSocket();
        }
    }

    private void receiveLoop() {
        long backoff = config.minBackoffMs();
        boolean everConnected = false;
        while (!isClosed()) {
            Socket s;
            try {
                s = config.tls() == null ? new Socket() : config.tls().getSocketFactory().createSocket();
            } catch (IOException e) {
                problem("cannot make a socket: " + e.getMessage(), false);
                return;
            }
            boolean up = false;
            try {
                s.connect(new InetSocketAddress(config.host(), config.port()), HANDSHAKE_TIMEOUT_MS);
                socket = s;
                localAddress = s.getLocalSocketAddress();
                if (s instanceof SSLSocket tlsSocket) {
                    var params = tlsSocket.getSSLParameters();
                    params.setEndpointIdentificationAlgorithm("HTTPS"); // the certificate must name the host
                    tlsSocket.setSSLParameters(params);
                    tlsSocket.setSoTimeout(HANDSHAKE_TIMEOUT_MS);
                    tlsSocket.startHandshake();
                }
                s.setTcpNoDelay(true);
                s.setSoTimeout(HANDSHAKE_TIMEOUT_MS);
                var out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                // the middleware proves it holds the secret before it may drive (and so do we)
                Handshake.asController(new DataInputStream(s.getInputStream()), out, hello, config.secret());
                s.setSoTimeout(0);
                outbox.clear();
                SensorDataWriter w = new SensorDataWriter(s.getOutputStream(), config.resetEvery());
                w.measure(costs);
                writer = w;
                up = true;
                everConnected = true;
                backoff = config.minBackoffMs();
                config.log().accept("connected to the middleware at " + config.host() + ":" + config.port());
                CommandReader reader = new CommandReader(s.getInputStream(), config.clock());
                if (config.lockstep()) {
                    LentReader l = new LentReader(reader);
                    lent = l;
                    inbox.connectionChanged(true);
                    l.awaitEnd();
                } else {
                    inbox.connectionChanged(true);
                    readCommands(reader);
                }
            } catch (ProtocolException | AuthenticationException e) {
                problem(e.getMessage(), up);
            } catch (SocketTimeoutException e) {
                problem("the middleware did not answer the handshake", up);
            } catch (IOException e) {
                if (up || !everConnected && lastProblem == null) {
                    problem(up ? "link dropped: " + e.getMessage()
                            : "waiting for the middleware at " + config.host() + ":" + config.port() + " (" + e.getMessage() + ")", up);
                }
            } finally {
                lent = null;
                writer = null;
                localAddress = null;
                closeSocket();
                if (up) {
                    inbox.connectionChanged(false);
                }
            }
            if (!isClosed()) {
                try {
                    closed.await(backoff, TimeUnit.MILLISECONDS);
                } catch (InterruptedException e) {
                    return;
                }
                backoff = Math.min(config.maxBackoffMs(), backoff * 2);
            }
        }
    }

    /** One connection, made at once: the middleware end listens already (no handshake, see {@link MemoryLink}). */
    private void connectInMemory() {
        try {
            SensorDataWriter w = new SensorDataWriter(memory.controllerOut(), config.resetEvery());
            w.measure(costs);
            CommandReader reader = new CommandReader(memory.controllerIn(), config.clock());
            memory.connect(hello, w, new MemoryLink.Reader() {
                @Override
                public void read(long frames) {
                    try {
                        for (long i = 0; i < frames; i++) {
                            accept(reader.read());
                        }
                    } catch (IOException e) {
                        memory.close("garbage from the middleware: " + e.getMessage());
                    }
                }

                @Override
                public void closed(String reason) {
                    writer = null;
                    if (!isClosed()) { // no reconnecting: the wheels stop and lockstep waits for close()
                        lastProblem = reason;
                        config.log().accept(reason + "; the wheels are stopped");
                        inbox.connectionChanged(false);
                    }
                }
            });
            writer = w;
            config.log().accept("connected to the middleware in this process");
            inbox.connectionChanged(true);
        } catch (IOException e) {
            problem("cannot connect to the middleware in this process: " + e.getMessage(), false);
        }
    }

    /**
     * Lockstep over TCP, simulation thread, after writing step {@code step}: the middleware's turn
     * on this thread when it is in this process ({@code turn}, or null), then reads its commands up
     * to its {@code STEP_ACK(step)}. Reading here rather than on the receiver thread saves a thread
     * wake-up per step: the receiver's hand-off to this thread; taking the middleware's turn here
     * saves its reading thread's. A failure ends the connection; {@code awaitAck} then reports it.
     */
    void readAnswer(long step, LockstepTurn turn) {
        LentReader l = lent;
        SocketAddress here = localAddress;
        if (l != null) {
            boolean answered = false;
            if (turn != null && here != null && l.turns.takes()) {
                answered = turn.take(here, step);
                if (l.turns.taken()) {
                    turn.release(); // a busy machine: the middleware's reading thread serves from now on
                }
            }
            l.readUntilAck(step, answered);
        }
    }

    /**
     * A lockstep connection's command stream, lent by the receiver thread to the simulation thread,
     * which reads it at each step; the receiver waits for the connection's end to reconnect.
     */
    private final class LentReader {
        private final CommandReader reader;
        private final LockstepSpin spin = new LockstepSpin();
        /** Whether the simulation thread still takes the middleware's turns (in one process). */
        private final TurnWatch turns = new TurnWatch();
        private final LockstepSpin.Ready answerReady;
        private final CountDownLatch ended = new CountDownLatch(1);
        private volatile IOException failure;

        LentReader(CommandReader reader) {
            this.reader = reader;
            this.answerReady = reader::ready;
        }

        /** @param answered whether the answer has been written already (no spin then) */
        void readUntilAck(long step, boolean answered) {
            try {
                while (!inbox.hasAck(step) && ended.getCount() > 0) {
                    if (!answered) {
                        spin.await(answerReady);
                    }
                    ReceivedCommand rc = reader.read();
                    if (rc == null) {
                        ended.countDown();
                        return;
                    }
                    accept(rc);
                }
            } catch (IOException e) {
                failure = e;
                ended.countDown();
            }
        }

        /** Receiver thread: returns when the middleware closed the stream, throws how else it ended. */
        void awaitEnd() throws IOException {
            try {
                ended.await();
            } catch (InterruptedException e) {
                return; // closing
            }
            if (failure != null) {
                throw failure;
            }
            if (!isClosed()) {
                problem("the middleware closed the connection", true);
            }
        }
    }

    private void readCommands(CommandReader reader) throws IOException {
        while (!isClosed()) {
            ReceivedCommand rc = reader.read();
            if (rc == null) {
                if (!isClosed()) {
                    problem("the middleware closed the connection", true);
                }
                return;
            }
            accept(rc);
        }
    }

    private void accept(ReceivedCommand rc) {
        if (rc.isValid()) {
            inbox.offer(rc);
        } else {
            config.log().accept("command frame " + rc.seq() + " skipped: " + rc.skipped());
        }
    }

    private void problem(String message, boolean wasUp) {
        if (isClosed()) {
            return;
        }
        lastProblem = message;
        config.log().accept(message + (wasUp ? "; the wheels are stopped, reconnecting" : ""));
    }

    private void closeSocket() {
        Socket s = socket;
        if (s != null) {
            try {
                s.close();
            } catch (IOException e) {
                // nothing more to do
            }
        }
    }
}
