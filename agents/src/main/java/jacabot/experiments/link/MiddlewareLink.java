package jacabot.experiments.link;

import jacabot.robot.link.Command;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkClock;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.LockstepTurn;
import jacabot.robot.link.MemoryLink;
import jacabot.robot.link.Protocol;
import java.io.IOException;
import java.net.ServerSocket;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * The middleware's end of the link (thesis §2.3), as a plain class that the {@code MiddlewareArtifact}
 * wraps: one robot's controller, which connects, proves it holds the link secret
 * ({@link Handshake}; only then may a new connection replace the old one, so a
 * controller that reconnects after a drop is taken back at once and nobody else is), streams its
 * sensor data and takes commands. This class is the link's face; each job is one of its parts:
 * <ul>
 *   <li>{@link LinkListener}: binds (plain or TLS) and accepts; {@link HandshakeGuard}: counts and
 *       rate-limits failed handshakes; {@link ConnectionWatchdog}: closes slow handshakes and frames;</li>
 *   <li>{@link ControllerSession}: which connection is the robot's, and what its frames become;
 *       {@link ClockRebase}: a restarted controller's clock continues the last time seen;</li>
 *   <li>{@link EventQueue}: the {@link LinkEvent}s on their way to the middleware;</li>
 *   <li>{@link CommandStream}: the commands out and their {@code APPLIED} reports ({@link LinkTimings});</li>
 *   <li>{@link Heartbeat}, {@link StepAcknowledgement}: heartbeats and lockstep acknowledgements,
 *       only while the agent reasons ({@link AgentProbes});</li>
 *   <li>{@link CallerTurn}: in one process, a lockstep connection read and answered on the
 *       controller's simulation thread ({@link #turnOnCaller}).</li>
 * </ul>
 * Each link has its own parts, so one process serves several robots' links; {@link LinkRegistry}
 * knows them all.
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
public final class MiddlewareLink implements AutoCloseable {
    private final LinkConfig config;
    private final LinkTimings timings;
    private final LinkCosts costs = new LinkCosts();
    private final EventQueue events;
    private final CommandStream commands;
    private final HandshakeGuard handshakes;
    private final ControllerSession session;
    private final AgentProbes agent = LinkRegistry.probes();
    private final StepAcknowledgement acks = new StepAcknowledgement(agent, this::acknowledge);
    private final CallerTurn turn = new CallerTurn();
    /** Null for an in-process link, as are the heartbeat and the watchdog. */
    private final LinkListener listener;
    private final Heartbeat heartbeat;
    private final ConnectionWatchdog watchdog;

    private MiddlewareLink(LinkConfig config, ServerSocket server) {
        this.config = config;
        this.timings = new LinkTimings(config.clock());
        this.events = new EventQueue(config.queueCapacity(), timings);
        this.commands = new CommandStream(config.clock(), timings, costs);
        this.handshakes = new HandshakeGuard(config.guards(), config.log());
        this.session = new ControllerSession(config, timings, events, commands, handshakes, this::forget);
        if (server == null) {
            listener = null;
            heartbeat = null;
            watchdog = null;
            return;
        }
        listener = new LinkListener(server, config, handshakes, session, costs, turn);
        watchdog = new ConnectionWatchdog(config.guards(), listener.live(), handshakes);
        heartbeat = new Heartbeat(config, session::current, commands, agent, acks, () -> send(Command.heartbeat()));
    }

    /**
     * Opens the server socket and starts accepting.
     *
     * @throws IOException when the address cannot be bound (e.g. the port is taken)
     */
    public static MiddlewareLink open(LinkConfig config) throws IOException {
        ServerSocket server = LinkListener.bind(config);
        config.secret(); // fails here, with the file's problem, rather than at the first connection
        MiddlewareLink link = new MiddlewareLink(config, server);
        LinkRegistry.opened(link);
        link.listener.start();
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
        memory.listen(hello -> RobotConnection.attachInMemory(memory, hello, link.session, config, link.costs));
        LinkRegistry.opened(link);
        return link;
    }

    /**
     * The controller is in this process and lockstep: its simulation thread, after writing each
     * step, reads the step from this end of the socket and answers it ({@link LockstepTurn}), so no
     * thread wakes up in a step. Call it before the controller connects, and give the turn to it
     * ({@code RobotController.takeTurnsWith}). A turn serves only the connection its step was written
     * on; another lockstep connection (it would have to prove the secret: an in-process run's is
     * fresh) stays lent until a turn, not finding its own within 5 s, releases the turns.
     * {@return the turn}
     */
    public LockstepTurn turnOnCaller() {
        if (listener == null) {
            throw new UnsupportedOperationException("an in-process link reads on the controller's thread already");
        }
        turn.enable();
        return turn;
    }

    /** {@return the port listened on (the chosen one when configured with 0); 0 for an in-process link} */
    public int port() {
        return listener == null ? 0 : listener.port();
    }

    public boolean isConnected() {
        return session.current() != null;
    }

    /** Waits until a controller is connected; {@return whether one is} */
    public boolean awaitConnected(long timeout, TimeUnit unit) throws InterruptedException {
        return session.awaitAttached(timeout, unit);
    }

    /** {@return the connected controller's greeting (robot, world, control step, mode), or null} */
    public Protocol.Hello robot() {
        RobotConnection c = session.current();
        return c == null ? null : c.hello();
    }

    /** {@return the simulated time of the latest step received, −1 before any} */
    public long simTimeMs() {
        return session.simTimeMs();
    }

    /** {@return why the last connection ended (or was refused), or null} */
    public String lastCloseReason() {
        return session.lastCloseReason();
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
        return handshakes.failedHandshakes();
    }

    /** {@return frames dropped as malformed or because handling them failed} */
    public long badFrames() {
        return session.badFrames();
    }

    /**
     * Heartbeats and lockstep acknowledgements go out only while {@code probe} says the agent reasons
     * (its reasoning cycle moves, or it is idle waiting for events): a stuck or dead agent then lets
     * the controller's fail-safe stop the robot, as a dead process would.
     */
    public void setLiveness(BooleanSupplier probe) {
        agent.setLiveness(probe);
    }

    /** Blocks until the next event: the body of the artifact's {@code IBlockingCmd.exec()}. */
    public LinkEvent receive() throws InterruptedException {
        return events.take();
    }

    /** {@return the next event, or null after the timeout} */
    public LinkEvent poll(long timeout, TimeUnit unit) throws InterruptedException {
        return events.poll(timeout, unit);
    }

    /**
     * From now on, every event goes to {@code handler} on the connection's reading thread, in order,
     * instead of the queue that {@link #receive()} reads; the events already queued go first. A
     * lockstep driver answers each step there, which saves a thread hand-off per step. The handler
     * must not throw.
     */
    public void handOver(Consumer<LinkEvent> handler) {
        events.handOver(handler);
    }

    /** Sends a command now; {@return false when no controller is connected or the socket failed} */
    public boolean send(Command command) {
        return send(command, config.clock().nowMicros());
    }

    /**
     * Sends a command on behalf of an agent action executed at {@code actionMicros}
     * ({@link LinkClock}): the response time runs from there to the controller's
     * report that the actuators got it.
     */
    public boolean send(Command command, long actionMicros) {
        return commands.send(session.current(), command, actionMicros);
    }

    /** Closes the current connection (the controller stops its wheels and reconnects). */
    public void disconnect(String reason) {
        RobotConnection c = session.current();
        if (c != null) {
            c.close(reason);
        }
    }

    /** Lockstep: the step's commands are all sent, the simulation may advance. */
    public boolean acknowledge(long step) {
        return send(Command.stepAck(step));
    }

    /**
     * Lockstep with the agent in another thread: acknowledges {@code step} now if the agent reasons
     * and is idle ({@link LinkRegistry#setDefaultQuiescence}), else as soon as it is (the heartbeat
     * thread retries), so a stuck agent holds the world still instead of letting it run without a mind.
     */
    public void acknowledgeWhenAlive(long step) {
        if (listener == null) {
            throw new UnsupportedOperationException("an in-process link has no heartbeat thread to retry an acknowledgement");
        }
        acks.whenAlive(step);
    }

    /**
     * Lockstep: sends a step's commands and its {@code STEP_ACK} in one write, so the controller
     * wakes once per step; {@return false when no controller is connected or the socket failed}
     */
    public boolean answerStep(List<Command> stepCommands, long step) {
        return commands.answerStep(session.current(), stepCommands, step);
    }

    @Override
    public void close() {
        LinkRegistry.closed(this);
        if (listener != null) {
            listener.stopAccepting();
        }
        session.close("the middleware closed the link");
        turn.release();
        if (listener != null) {
            listener.closeConnections("the middleware closed the link");
            heartbeat.stop();
            watchdog.stop();
        }
        session.wake();
    }

    /** A connection ended or was refused: the listener stops watching it. */
    private void forget(RobotConnection c) {
        if (listener != null) {
            listener.forget(c);
        }
    }
}
