package jacabot.experiments;

import jacabot.cartago.AgentId;
import jacabot.cartago.Artifact;
import jacabot.cartago.FollowingClock;
import jacabot.cartago.GUARD;
import jacabot.cartago.IBlockingCmd;
import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;
import jacabot.experiments.link.LinkConfig;
import jacabot.experiments.link.LinkEvent;
import jacabot.experiments.link.MiddlewareLink;
import jacabot.experiments.link.StepData;
import jacabot.robot.link.Command;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * The thesis' executive layer (Chapter 3 §2, Chapter 4 "Introduction"): the artifact between the
 * agent and the robot controller. It turns raw {@link SensorInfo} readings into observable
 * properties and signals, and offers the robot's high-level commands as operations.
 *
 * <p>Two ways to reach the robot. <b>Socket</b> ({@code makeArtifact(N, C, [Port], Id)}): the
 * artifact listens on loopback, {@code accept} waits for the controller and {@code acquireData}
 * starts the thesis' {@code servingLoop}, which reads one reading at a time with
 * {@code await(IBlockingCmd)}. <b>Lockstep</b> ({@code [Port, "lockstep"]}, made by the experiment
 * runner): the runner owns the socket and hands each control step's readings to
 * {@code deliverStep}; commands are collected and sent by the runner when the agents are idle.
 * Subclasses interpret the readings ({@link #onReading}).
 */
public abstract class MiddlewareArtifact extends Artifact {
    private MiddlewareLink link;
    private boolean lockstep;
    private final List<Command> outbox = new ArrayList<>();
    private boolean acquiring;
    private boolean stopAcquire;
    /** Distance sensors ignored (the thesis' {@code stopDistance}), e.g. inside the storage area. */
    protected boolean stopDistance;
    /** The reading being interpreted, for the reactive-time measurement. */
    private LinkEvent.Reading current;
    private long simTimeMs;
    /** A lockstep step marker handled, its acknowledgement not yet requested (−1: none). */
    private long ackDue = -1;
    private final WheelLease wheels = new WheelLease();

    /** The holder in {@code wheels(Holder)} while no agent holds the wheels. */
    public enum Wheels { FREE }

    /** What {@code failsafe(tripped)} says: the controller stopped the wheels on its own. */
    public enum FailSafe { TRIPPED }

    void init(int port) throws IOException {
        // the link's connections and closings go to the workspace's console as the artifact's lines
        // ([middleware] ...), not straight to stderr: the launcher's console decides what is shown
        link = MiddlewareLink.open(LinkConfig.defaults().withPort(port).withLog(this::linkLog));
        defineObsProperty("connected", false);
        defineProperties();
    }

    /** A line of the link's (its threads call it, also while the workspace closes). */
    private void linkLog(String line) {
        try {
            log(line);
        } catch (RuntimeException e) {
            System.err.println("[middleware] " + line); // the workspace is gone: as before, on stderr
        }
    }

    void init(int port, String mode) throws IOException {
        if (!mode.equals("lockstep")) {
            failed("unknown middleware mode '" + mode + "' (expected \"lockstep\")");
        }
        lockstep = true;
        defineObsProperty("connected", false);
        defineProperties();
    }

    /** Defines the experiment's observable properties. */
    protected abstract void defineProperties();

    /** Interprets one reading: update properties, signal events. */
    protected abstract void onReading(SensorInfo info, SensorKind kind);

    /** {@return the simulated time of the last reading, in ms} */
    protected long simTimeMs() {
        return simTimeMs;
    }

    /** {@return the reading being interpreted (null in lockstep)} */
    protected LinkEvent.Reading currentReading() {
        return current;
    }

    private volatile LinkEvent.Reading lastTrigger;

    /**
     * Notes that the reading being interpreted changed what the agent perceives (a property or a
     * signal): the reactive time is measured from its sampling to the plan it triggers.
     */
    protected void markTrigger() {
        if (current != null) {
            lastTrigger = current;
        }
    }

    /** {@return the reading that last changed what the agent perceives, once; null if none since} */
    public LinkEvent.Reading takeTrigger() {
        LinkEvent.Reading r = lastTrigger;
        lastTrigger = null;
        return r;
    }

    /** The socket link in socket mode, for timings; null in lockstep. */
    public MiddlewareLink link() {
        return link;
    }

    // ---- the connection ---------------------------------------------------------------------------

    /** Waits for the robot controller to connect (the thesis' {@code accept}). */
    @OPERATION
    void accept() {
        if (lockstep) {
            return; // the runner connects; deliverStep sets connected(true)
        }
        if (!link.isConnected()) {
            await((IBlockingCmd) () -> {
                try {
                    while (!link.awaitConnected(1, TimeUnit.SECONDS)) {
                        if (Thread.currentThread().isInterrupted()) {
                            return;
                        }
                    }
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
        }
        getObsProperty("connected").updateValue(true);
    }

    /** Starts interpreting sensor data (the thesis' {@code acquireData} → {@code servingLoop}). */
    @OPERATION
    void acquireData() {
        log("Acquiring data");
        acquiring = true;
        stopAcquire = false;
        if (!lockstep) {
            execInternalOp("servingLoop");
        }
    }

    @INTERNAL_OPERATION
    void servingLoop() {
        while (!stopAcquire) {
            LinkEvent[] next = new LinkEvent[1];
            long ack = ackDue;
            ackDue = -1;
            await((IBlockingCmd) () -> {
                if (ack >= 0) {
                    // here the step's property changes are out: the link acknowledges once the agent
                    // has taken them in and is idle again
                    link.acknowledgeWhenAlive(ack);
                }
                try {
                    next[0] = link.receive();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            if (next[0] != null) {
                try {
                    handle(next[0]);
                } catch (RuntimeException e) {
                    // one bad reading must not end the serving loop: the agent would be blind for good
                    log("reading dropped, interpreting it failed: " + e);
                }
            }
        }
    }

    private void handle(LinkEvent e) {
        if (e instanceof LinkEvent.Connected) {
            getObsProperty("connected").updateValue(true);
        } else if (e instanceof LinkEvent.Disconnected) {
            getObsProperty("connected").updateValue(false);
        } else if (e instanceof LinkEvent.FailSafe) {
            signal("failsafe", FailSafe.TRIPPED); // the agent may plan for it: +failsafe(tripped)
        } else if (e instanceof LinkEvent.StepMarker m) {
            if (m.awaitsAck()) {
                // a lockstep controller in another process: the world waits for this (see servingLoop)
                ackDue = m.step();
            }
        } else if (e instanceof LinkEvent.Reading r) {
            simTimeMs = r.simTimeMs();
            if (getClock() instanceof FollowingClock following) {
                following.follow(simTimeMs); // .wait and await_time count simulated time
            }
            Optional<SensorKind> kind = SensorKind.of(r.info().getId());
            if (kind.isPresent() && acquiring) {
                current = r;
                onReading(r.info(), kind.get());
                current = null;
            }
        }
    }

    /** Lockstep: the runner hands over one control step's readings. */
    @OPERATION
    void deliverStep(Object data) {
        StepData step = (StepData) data;
        simTimeMs = step.simTimeMs();
        if (!getObsProperty("connected").booleanValue()) {
            getObsProperty("connected").updateValue(true);
        }
        if (!acquiring || stopAcquire) {
            return;
        }
        for (SensorInfo info : step.readings()) {
            SensorKind.of(info.getId()).ifPresent(kind -> onReading(info, kind));
        }
    }

    /** {@return the commands issued since the last call (lockstep)} */
    public synchronized List<Command> takeCommands() {
        wheels.endStep();
        var out = new ArrayList<>(outbox);
        outbox.clear();
        return out;
    }

    /** Sends a command to the robot. */
    protected void send(Command c) {
        if (lockstep) {
            synchronized (this) {
                outbox.add(c);
            }
        } else if (!link.send(c)) {
            failed("the robot is not connected", "not_connected");
        }
    }

    @OPERATION
    void stopAcquire() {
        stopAcquire = true;
        acquiring = false;
    }

    @OPERATION
    void stopAcquireDistance() {
        stopDistance = true;
    }

    @OPERATION
    void restartAcquireDistance() {
        stopDistance = false;
    }

    // ---- the wheels, one agent's at a time --------------------------------------------------------

    /**
     * The caller holds the wheels until it releases them; waits while another agent holds them
     * (not in the thesis: one robot, several agents). Observable: {@code wheels(Holder)}, defined
     * at the first call ({@code free} when released), so an agent alone on its robot never sees it.
     */
    @OPERATION
    void acquireWheels() {
        AgentId me = getCurrentOpAgentId();
        await("wheelsFreeFor", me.name());
        wheels.hold(me.name());
        showWheels(me);
    }

    @GUARD
    boolean wheelsFreeFor(String agent) {
        return wheels.isFreeFor(agent);
    }

    /** The caller lets the wheels go (it did not hold them: nothing happens). */
    @OPERATION
    void releaseWheels() {
        if (wheels.release(getCurrentOpAgentId().name())) {
            showWheels(Wheels.FREE);
        }
    }

    private void showWheels(Object holder) {
        if (hasObsProperty("wheels")) {
            updateObsProperty("wheels", holder);
        } else {
            defineObsProperty("wheels", holder);
        }
    }

    /** {@return who holds the wheels, whose commands went through in this step and how many were refused} */
    public WheelLease wheelLease() {
        return wheels;
    }

    /**
     * Sends a wheel command, unless the wheels are leased ({@link WheelLease}) and the caller does not
     * hold them, or another agent drove them in this step: then the operation fails
     * ({@code wheels_held_by(Holder)}, {@code wheels_not_held}).
     */
    private void drive(Command c) {
        String me = getCurrentOpAgentId().name();
        var refusal = wheels.command(me);
        if (refusal.isPresent()) {
            var holder = wheels.holder();
            if (holder.isPresent()) {
                failed(me + " may not command the wheels: " + refusal.get(), "wheels_held_by", new AgentId(holder.get()));
            }
            failed(me + " may not command the wheels: " + refusal.get(), "wheels_not_held");
        }
        send(c);
    }

    // ---- robot commands -------------------------------------------------------------------------

    @OPERATION
    void setSpeeds(double left, double right) {
        drive(Command.setSpeeds(left, right));
    }

    @OPERATION
    void stop() {
        drive(Command.stop());
    }

    @OPERATION
    void forward() {
        drive(Command.forward());
    }

    @OPERATION
    void backward() {
        drive(Command.backward());
    }

    @OPERATION
    void turnLeft() {
        drive(Command.turnLeft());
    }

    @OPERATION
    void turnRight() {
        drive(Command.turnRight());
    }

    @OPERATION
    void turnAround() {
        drive(Command.turnAround());
    }

    @Override
    protected void dispose() {
        if (link != null) {
            link.close();
        }
    }
}
