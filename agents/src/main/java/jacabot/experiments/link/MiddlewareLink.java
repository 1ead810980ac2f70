package jacabot.experiments.link;

import jacabot.robot.link.Command;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.MemoryLink;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.Uplink;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingDeque;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingDeque;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * The middleware's end of the link (thesis §2.3: the artifact "creates a new ServerSocket on a
 * well-known port, waits for a connection request from the robot platform"), as a plain class that
 * the {@code MiddlewareArtifact} wraps. It listens on loopback by default, accepts the controller,
 * checks the protocol version and that the controller holds the link secret
 * ({@link jacabot.robot.link.Handshake}; only then may a new connection replace the old one, so a
 * controller that reconnects after a drop is taken back at once and nobody else is), reads the
 * sensor data stream on its own thread and queues {@link LinkEvent}s, and writes commands.
 *
 * <p>Guards: failed handshakes are logged and rate-limited; a handshake or a frame that takes too
 * long closes its connection (a watchdog thread); a controller whose simulated clock went back
 * (it restarted) is rebased so that the time the agent sees never goes back; heartbeats only go
 * out while the agent reasons ({@link #setLiveness}), so the controller's fail-safe stops the robot
 * when the agent is stuck or dead, not only when this process is.
 *
 * <p>{@link #inMemory} makes the same end for a controller of this process, over a
 * {@link MemoryLink} instead of a socket (sweeps): no port, no handshake, no threads.
 *
 * <p>For CArtAgO: one {@link #receive()} is one {@code await(IBlockingCmd)}: its {@code exec()}
 * blocks until the next reading, step marker or connection change arrives.
 *
 * <pre>{@code
 * try (MiddlewareLink link = MiddlewareLink.open(LinkConfig.defaults().withPort(0))) {
 *     LinkEvent e = link.receive();                 // blocks
 *     if (e instanceof LinkEvent.Reading r && r.info().getVal() > 350) link.send(Command.stop());
 *     if (e instanceof LinkEvent.StepMarker m && m.awaitsAck()) link.acknowledge(m.step());
 * }
 * }</pre>
 */
public final class MiddlewareLink implements AutoCloseable, RobotConnection.Owner {
    /** Told when the controller connects or goes ({@code connected(true|false)}). */
    @FunctionalInterface
    public interface ConnectionListener {
        void connectionChanged(boolean connected);
    }

    private static final int PENDING_RESPONSES = 10_000;

    /** A robot command on its way: when the agent's action sent it, and the lockstep step it answered (or −1). */
    private record Sent(long actionMicros, long step) {
    }

    private final LinkConfig config;
    private final ServerSocket server;
    private final BlockingDeque<LinkEvent> events = new LinkedBlockingDeque<>();
    private final List<ConnectionListener> listeners = new CopyOnWriteArrayList<>();
    private final AtomicInteger seq = new AtomicInteger();
    private final LinkTimings timings;
    private final LinkCosts costs = new LinkCosts();
    private final Map<Integer, Sent> inFlight = new LinkedHashMap<>(16, 0.75f, false) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(Map.Entry<Integer, Sent> eldest) {
            return size() > PENDING_RESPONSES; // commands whose APPLIED report never came
        }
    };
    private volatile RobotConnection current;
    /** Set by {@link #handOver}: events go to it on the reading thread, not to the queue. */
    private Consumer<LinkEvent> handler;
    private final Object dispatch = new Object();
    private volatile long simTimeMs = -1;
    private volatile long lastSentNanos = System.nanoTime();
    private volatile String lastCloseReason;
    private volatile boolean closed;
    private final Thread acceptor;
    private final Thread heartbeat;
    private final Thread watchdog;
    /** Connections not yet closed: the watchdog checks their handshake and frame deadlines. */
    private final java.util.Set<RobotConnection> live = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private volatile java.util.function.BooleanSupplier liveness = defaultLiveness;
    private static volatile java.util.function.BooleanSupplier defaultLiveness = () -> true;
    private volatile boolean withheld;
    /** Failed handshakes: this second's count, the second it counts, those refused unheard, all. */
    private long failedThisSecond, failureSecond, rateLimited;
    private final java.util.concurrent.atomic.AtomicLong failedHandshakes = new java.util.concurrent.atomic.AtomicLong();
    private final java.util.concurrent.atomic.AtomicLong badFrames = new java.util.concurrent.atomic.AtomicLong();
    private volatile long loggedFailures;
    /** Simulated time seen last, and what is added to a restarted controller's clock. */
    private volatile long lastSimTimeMs = -1;
    private long timeOffsetMs;
    private boolean rebaseChecked;

    private MiddlewareLink(LinkConfig config, ServerSocket server) {
        this.config = config;
        this.server = server;
        this.timings = new LinkTimings(config.clock());
        this.acceptor = new Thread(this::acceptLoop, "middleware-acceptor");
        this.heartbeat = new Thread(this::heartbeatLoop, "middleware-heartbeat");
        this.watchdog = new Thread(this::watchdogLoop, "middleware-watchdog");
        acceptor.setDaemon(true);
        heartbeat.setDaemon(true);
        watchdog.setDaemon(true);
    }

    /**
     * Opens the server socket and starts accepting.
     *
     * @throws IOException when the address cannot be bound (e.g. the port is taken)
     */
    public static MiddlewareLink open(LinkConfig config) throws IOException {
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
        config.secret(); // fails here, with the file's problem, rather than at the first connection
        MiddlewareLink link = new MiddlewareLink(config, server);
        OPEN.add(link);
        link.acceptor.start();
        link.watchdog.start();
        if (config.heartbeatMs() > 0) {
            link.heartbeat.start();
        }
        return link;
    }

    /**
     * The middleware end of an in-process link ({@link MemoryLink}): no port, no handshake, no
     * thread of its own. The controller's frames are handled on the thread that writes them, its
     * simulation thread; for lockstep runs answered through {@link #handOver} and {@link #answerStep}.
     */
    public static MiddlewareLink inMemory(LinkConfig config, MemoryLink memory) {
        MiddlewareLink link = new MiddlewareLink(config, null);
        memory.listen(hello -> RobotConnection.attachInMemory(memory, hello, link, config, link.costs));
        OPEN.add(link);
        return link;
    }

    /** {@return the port listened on (the chosen one when configured with 0); 0 for an in-process link} */
    public int port() {
        return server == null ? 0 : server.getLocalPort();
    }

    public boolean isConnected() {
        return current != null;
    }

    /** Waits until a controller is connected; {@return whether one is} */
    public boolean awaitConnected(long timeout, TimeUnit unit) throws InterruptedException {
        long end = System.nanoTime() + unit.toNanos(timeout);
        synchronized (this) {
            while (current == null && !closed) {
                long left = end - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                TimeUnit.NANOSECONDS.timedWait(this, left);
            }
            return current != null;
        }
    }

    /** {@return the connected controller's greeting (robot, world, control step, mode), or null} */
    public Protocol.Hello robot() {
        RobotConnection c = current;
        return c == null ? null : c.hello();
    }

    /** {@return the simulated time of the latest step received, −1 before any} */
    public long simTimeMs() {
        return simTimeMs;
    }

    /** {@return why the last connection ended (or was refused), or null} */
    public String lastCloseReason() {
        return lastCloseReason;
    }

    public LinkTimings timings() {
        return timings;
    }

    /** {@return the time spent decoding the controller's frames so far} */
    public LinkCosts costs() {
        return costs;
    }

    /** {@return handshakes that failed (wrong secret, garbage, timeout), refused ones included} */
    public long failedHandshakes() {
        return failedHandshakes.get();
    }

    /** {@return frames dropped as malformed or because handling them failed} */
    public long badFrames() {
        return badFrames.get();
    }

    /**
     * Heartbeats go out only while {@code probe} says the agent reasons (its reasoning cycle moves, or
     * it is idle waiting for events): a stuck or dead agent then lets the controller's fail-safe stop
     * the robot, as a dead process would.
     */
    public void setLiveness(java.util.function.BooleanSupplier probe) {
        this.liveness = probe;
    }

    /** The liveness probe of links opened from now on in this process (the launcher sets the agents'). */
    public static void setDefaultLiveness(java.util.function.BooleanSupplier probe) {
        defaultLiveness = probe;
    }

    private volatile java.util.function.BooleanSupplier quiescence = defaultQuiescence;
    private static volatile java.util.function.BooleanSupplier defaultQuiescence = () -> true;

    /**
     * Lockstep with the agent in its own thread: a step is acknowledged once {@code probe} says the
     * agent is idle (it has taken the step's percepts in and acted on them), as the in-process
     * lockstep runner does; by default at once.
     */
    public void setQuiescence(java.util.function.BooleanSupplier probe) {
        this.quiescence = probe;
    }

    /** The quiescence probe of links opened from now on in this process. */
    public static void setDefaultQuiescence(java.util.function.BooleanSupplier probe) {
        defaultQuiescence = probe;
    }

    public void addConnectionListener(ConnectionListener l) {
        listeners.add(l);
    }

    /** Blocks until the next event: the body of the artifact's {@code IBlockingCmd.exec()}. */
    public LinkEvent receive() throws InterruptedException {
        return delivered(events.take());
    }

    /** {@return the next event, or null after the timeout} */
    public LinkEvent poll(long timeout, TimeUnit unit) throws InterruptedException {
        return delivered(events.poll(timeout, unit));
    }

    /**
     * From now on, every event goes to {@code handler} on the connection's reading thread, in order,
     * instead of the queue that {@link #receive()} reads; the events already queued go first. A
     * lockstep driver answers each step there, which saves a thread hand-off per step. The handler
     * must not throw.
     */
    public void handOver(Consumer<LinkEvent> handler) {
        synchronized (dispatch) {
            for (LinkEvent e = events.poll(); e != null; e = events.poll()) {
                handler.accept(delivered(e));
            }
            this.handler = handler;
        }
    }

    private void dispatch(LinkEvent e) {
        synchronized (dispatch) {
            if (handler != null) {
                handler.accept(delivered(e));
                return;
            }
            if (e instanceof LinkEvent.Reading || e instanceof LinkEvent.StepMarker || e instanceof LinkEvent.FailSafe) {
                enqueue(e);
            } else {
                events.add(e); // connection changes are never dropped
            }
        }
    }

    private LinkEvent delivered(LinkEvent e) {
        if (e instanceof LinkEvent.Reading) {
            timings.delivered((LinkEvent.Reading) e);
        }
        return e;
    }

    /** Sends a command now; {@return false when no controller is connected or the socket failed} */
    public boolean send(Command command) {
        return send(command, config.clock().nowMicros());
    }

    /**
     * Sends a command on behalf of an agent action executed at {@code actionMicros}
     * ({@link jacabot.robot.link.LinkClock}): the response time runs from there to the controller's
     * report that the actuators got it.
     */
    public boolean send(Command command, long actionMicros) {
        RobotConnection c = current;
        if (c == null) {
            return false;
        }
        int n = number(command, actionMicros, -1);
        try {
            c.send(n, config.clock().nowMicros(), command);
            lastSentNanos = System.nanoTime();
            return true;
        } catch (IOException e) {
            c.close("cannot send " + command + ": " + e.getMessage());
            return false;
        }
    }

    /**
     * {@return the next sequence number, given to {@code command}}; a robot command is remembered
     * until its {@code APPLIED} report, with when the agent sent it and the lockstep step it answers (−1: none).
     */
    private int number(Command command, long actionMicros, long step) {
        int n = seq.incrementAndGet();
        if (command.code().isRobotCommand()) {
            synchronized (inFlight) {
                inFlight.put(n, new Sent(actionMicros, step));
            }
        }
        return n;
    }

    /** Closes the current connection (the controller stops its wheels and reconnects). */
    public void disconnect(String reason) {
        RobotConnection c = current;
        if (c != null) {
            c.close(reason);
        }
    }

    /** Lockstep: the step's commands are all sent, the simulation may advance. */
    public boolean acknowledge(long step) {
        return send(Command.stepAck(step));
    }

    private volatile long pendingAck = -1;

    /**
     * Lockstep with the agent in another thread: acknowledges {@code step} now if the agent reasons
     * ({@link #setLiveness}), else as soon as it does again (the heartbeat thread retries), so a stuck
     * agent holds the world still instead of letting it run without a mind.
     */
    public void acknowledgeWhenAlive(long step) {
        if (server == null) {
            throw new UnsupportedOperationException("an in-process link has no heartbeat thread to retry an acknowledgement");
        }
        if (alive() && quiet()) {
            pendingAck = -1;
            acknowledge(step);
        } else {
            pendingAck = step;
        }
    }

    private boolean quiet() {
        try {
            return quiescence.getAsBoolean();
        } catch (RuntimeException e) {
            return false;
        }
    }

    private boolean alive() {
        try {
            return liveness.getAsBoolean();
        } catch (RuntimeException e) {
            return false;
        }
    }

    /**
     * Lockstep: sends a step's commands and its {@code STEP_ACK} in one write, so the controller
     * wakes once per step; {@return false when no controller is connected or the socket failed}
     */
    public boolean answerStep(List<Command> commands, long step) {
        RobotConnection c = current;
        if (c == null) {
            return false;
        }
        long now = config.clock().nowMicros();
        List<Command> frames = new ArrayList<>(commands);
        frames.add(Command.stepAck(step));
        int[] seqs = new int[frames.size()];
        for (int i = 0; i < frames.size(); i++) {
            seqs[i] = number(frames.get(i), now, step);
        }
        try {
            long t0 = System.nanoTime();
            c.send(seqs, now, frames);
            lastSentNanos = System.nanoTime();
            costs.addWriting(lastSentNanos - t0);
            return true;
        } catch (IOException e) {
            c.close("cannot send the answer to step " + step + ": " + e.getMessage());
            return false;
        }
    }

    private static final java.util.Set<MiddlewareLink> OPEN = java.util.concurrent.ConcurrentHashMap.newKeySet();

    /**
     * Closes every link of this process at once (the launcher, when an agent's thread died): the
     * controllers see the drop and stop their robots without waiting for the process to end.
     */
    public static void closeAll() {
        for (MiddlewareLink l : OPEN) {
            l.close();
        }
    }

    @Override
    public void close() {
        OPEN.remove(this);
        closed = true;
        try {
            if (server != null) {
                server.close();
            }
        } catch (IOException e) {
            // closing anyway
        }
        RobotConnection c = current;
        if (c != null) {
            c.close("the middleware closed the link");
        }
        for (RobotConnection other : live) {
            other.close("the middleware closed the link");
        }
        acceptor.interrupt();
        heartbeat.interrupt();
        watchdog.interrupt();
        synchronized (this) {
            notifyAll();
        }
    }

    private void acceptLoop() {
        while (!closed) {
            try {
                Socket s = server.accept();
                String busy = refuseAtOnce();
                if (busy != null) {
                    s.close(); // not even a thread for it
                    continue;
                }
                RobotConnection c = new RobotConnection(s, this, config, costs);
                live.add(c);
                c.start();
            } catch (IOException e) {
                if (!closed) {
                    config.log().accept("accept failed: " + e.getMessage());
                }
            }
        }
    }

    /** {@return why a new connection is closed unheard (rate limit, too many handshakes), or null} */
    private String refuseAtOnce() {
        long second = System.nanoTime() / 1_000_000_000L;
        synchronized (failedHandshakes) {
            if (second == failureSecond && failedThisSecond >= config.guards().failedPerSecond()) {
                rateLimited++;
                failedHandshakes.incrementAndGet();
                return "rate-limited";
            }
        }
        long pending = live.stream().filter(c -> !c.handshakeDone()).count();
        if (pending >= config.guards().pendingHandshakes()) {
            failedHandshakes.incrementAndGet();
            return "too many handshakes at once";
        }
        return null;
    }

    /**
     * Heartbeats, sent only while the agent reasons: it is the agent's progress, not this thread's,
     * that keeps the controller's fail-safe quiet.
     */
    private void heartbeatLoop() {
        long periodNanos = TimeUnit.MILLISECONDS.toNanos(config.heartbeatMs());
        try {
            while (!closed) {
                // a pending lockstep acknowledgement is retried every millisecond
                Thread.sleep(pendingAck >= 0 ? 1 : Math.max(1, config.heartbeatMs() / 2));
                RobotConnection c = current;
                long ack = pendingAck;
                if (c != null && ack >= 0 && alive() && quiet()) {
                    pendingAck = -1;
                    acknowledge(ack);
                }
                // Lockstep controllers do not watch for silence: the world waits for us anyway.
                if (c != null && !c.hello().lockstep() && System.nanoTime() - lastSentNanos >= periodNanos) {
                    boolean alive = alive();
                    if (alive) {
                        if (withheld) {
                            withheld = false;
                            config.log().accept("the agent reasons again: heartbeats resume");
                        }
                        send(Command.heartbeat());
                    } else if (!withheld) {
                        withheld = true;
                        config.log().accept("the agent does not reason: heartbeats withheld, "
                                + "the controller's fail-safe will stop the robot");
                    }
                }
            }
        } catch (InterruptedException e) {
            // closing
        }
    }

    /** Closes connections that take too long to shake hands or to finish a frame; reports failed handshakes. */
    private void watchdogLoop() {
        long handshakeNanos = TimeUnit.MILLISECONDS.toNanos(config.guards().handshakeMs());
        long frameNanos = TimeUnit.MILLISECONDS.toNanos(config.guards().frameMs());
        try {
            while (!closed) {
                Thread.sleep(50);
                long now = System.nanoTime();
                for (RobotConnection c : live) {
                    if (c.isClosed()) {
                        continue;
                    }
                    if (!c.handshakeDone() && now - c.startedNanos() > handshakeNanos) {
                        c.close("no complete handshake within " + config.guards().handshakeMs() + " ms");
                    }
                    long frameStart = c.frameStartNanos();
                    if (frameStart != 0 && now - frameStart > frameNanos) {
                        c.close("a frame took longer than " + config.guards().frameMs() + " ms to arrive");
                    }
                }
                reportFailures();
            }
        } catch (InterruptedException e) {
            // closing
        }
    }

    /** Logs failed handshakes beyond the first five (logged one by one): at most one line a second. */
    private void reportFailures() {
        long n = failedHandshakes.get();
        long second = System.nanoTime() / 1_000_000_000L;
        if (n > loggedFailures && second != lastSummarySecond) {
            long limited;
            synchronized (failedHandshakes) {
                limited = rateLimited;
            }
            config.log().accept((n - loggedFailures) + " more failed connection attempts (" + limited
                    + " refused unheard by the rate limit so far)");
            loggedFailures = n;
            lastSummarySecond = second;
        }
    }

    private long lastSummarySecond = -1;

    @Override
    public void attached(RobotConnection c) {
        // only a controller that proved the secret gets here: it may take the robot over
        RobotConnection old;
        synchronized (this) {
            old = current;
            current = c;
            notifyAll();
        }
        if (old != null) {
            old.close("replaced by a new authenticated connection from the controller");
        }
        synchronized (dispatch) {
            rebaseChecked = false;
        }
        Protocol.Hello h = c.hello();
        config.log().accept("controller connected: robot '" + h.robotName() + "' of world '" + h.worldName() + "', "
                + (h.lockstep() ? "lockstep" : "real time") + ", control step " + h.controlStepMs() + " ms");
        dispatch(new LinkEvent.Connected(h.robotName(), h.worldName(), h.controlStepMs(), h.lockstep()));
        for (ConnectionListener l : listeners) {
            l.connectionChanged(true);
        }
    }

    @Override
    public void refused(RobotConnection c, String reason, boolean authentication) {
        live.remove(c);
        lastCloseReason = reason;
        long n = failedHandshakes.incrementAndGet();
        long second = System.nanoTime() / 1_000_000_000L;
        synchronized (failedHandshakes) {
            if (second != failureSecond) {
                failureSecond = second;
                failedThisSecond = 0;
            }
            failedThisSecond++;
        }
        if (n <= 5) {
            loggedFailures = n;
            config.log().accept("refused a connection: " + reason);
        }
    }

    @Override
    public void badFrame(RobotConnection c, String reason) {
        long n = badFrames.incrementAndGet();
        if (n <= 20 || n % 1000 == 0) {
            config.log().accept("bad frame dropped (" + n + " so far): " + reason);
        }
    }

    /**
     * {@return the simulated time the agent sees for a controller's {@code raw} time}: a controller
     * that restarted counts from 0 again, so its clock is moved on to continue from the last time
     * seen (one control step later) and .wait and timeouts in the agent keep working.
     */
    private long rebase(RobotConnection c, long raw) {
        if (!rebaseChecked) {
            rebaseChecked = true;
            if (lastSimTimeMs >= 0 && raw + timeOffsetMs < lastSimTimeMs) {
                timeOffsetMs = lastSimTimeMs + c.hello().controlStepMs() - raw;
                config.log().accept("the controller's simulated clock went back to " + raw + " ms (a restart): "
                        + "times are moved on by " + timeOffsetMs + " ms");
            }
        }
        long t = raw + timeOffsetMs;
        lastSimTimeMs = Math.max(lastSimTimeMs, t);
        return t;
    }

    @Override
    public void frame(RobotConnection c, Uplink frame) {
        if (c != current) {
            return; // a replaced connection's last words
        }
        if (frame instanceof Uplink.Batch) {
            Uplink.Batch b = (Uplink.Batch) frame;
            long received = config.clock().nowMicros();
            long t;
            synchronized (dispatch) {
                t = rebase(c, b.simTimeMs());
            }
            simTimeMs = t;
            for (var info : b.readings()) {
                LinkEvent.Reading r = new LinkEvent.Reading(info, b.step(), t, b.sampledMicros(), received);
                timings.received(r);
                dispatch(r);
            }
        } else if (frame instanceof Uplink.StepMarker) {
            Uplink.StepMarker m = (Uplink.StepMarker) frame;
            long t;
            synchronized (dispatch) {
                t = rebase(c, m.simTimeMs());
            }
            dispatch(new LinkEvent.StepMarker(m.step(), t, m.awaitsAck()));
        } else if (frame instanceof Uplink.Applied) {
            Uplink.Applied a = (Uplink.Applied) frame;
            Sent sent;
            synchronized (inFlight) {
                sent = inFlight.remove(a.seq());
            }
            if (sent != null) {
                timings.applied(sent.actionMicros(), a.appliedMicros());
                if (sent.step() >= 0) {
                    timings.appliedSteps(a.step() - sent.step());
                }
            }
        } else if (frame instanceof Uplink.FailSafe) {
            Uplink.FailSafe f = (Uplink.FailSafe) frame;
            config.log().accept("the controller's fail-safe stopped the wheels: " + f.reason());
            dispatch(new LinkEvent.FailSafe(f.simTimeMs(), f.reason()));
        }
    }

    /** Bounded: when nobody reads, the oldest readings make room (connection events always stay). */
    private void enqueue(LinkEvent e) {
        if (events.size() >= config.queueCapacity()) {
            List<LinkEvent> kept = new ArrayList<>();
            LinkEvent old;
            while (events.size() >= config.queueCapacity() / 2 && (old = events.poll()) != null) {
                if (old instanceof LinkEvent.Connected || old instanceof LinkEvent.Disconnected) {
                    kept.add(old);
                }
            }
            for (int i = kept.size() - 1; i >= 0; i--) {
                events.addFirst(kept.get(i));
            }
        }
        events.add(e);
    }

    @Override
    public void detached(RobotConnection c, String reason) {
        live.remove(c);
        boolean wasCurrent;
        synchronized (this) {
            wasCurrent = current == c;
            if (wasCurrent) {
                current = null;
            }
            notifyAll();
        }
        lastCloseReason = reason;
        config.log().accept("connection closed: " + reason);
        if (wasCurrent) {
            dispatch(new LinkEvent.Disconnected(reason));
            for (ConnectionListener l : listeners) {
                l.connectionChanged(false);
            }
        }
    }
}
