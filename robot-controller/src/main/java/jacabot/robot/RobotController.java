package jacabot.robot;
import jacabot.robot.link.Readings;

import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.LockstepTurn;
import jacabot.robot.link.MemoryLink;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.ReceivedCommand;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.Uplink;
import jacabot.sim.geom.Pose;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import java.util.List;
import java.util.function.Supplier;

/**
 * The robot controller process of the thesis (Chapter 3 §2.3–2.4), run against a sim-world robot
 * as Webots runs a controller: every control step it samples the enabled devices, sends one
 * {@link SensorInfo} per reading (with the step's simulated time) to the middleware, and applies the
 * commands received. {@link #controlStep(SimWorld)} is the body of Webots'
 * {@code while (robot.step(TIME_STEP) != -1)} loop; a {@link SimRunner} calls it before each step.
 *
 * <p>Two modes. <b>Real time</b>: the runner paces the world to the wall clock × a factor, the
 * agent runs free, commands take effect when they arrive (between two physics steps), and a fail-safe stops
 * the wheels when the link drops or nothing (command or heartbeat) has come for
 * {@code failSafeMs}. <b>Lockstep</b>: after sending a step's data and its step marker the
 * controller waits for the middleware's {@code STEP_ACK(step)}, applies the commands that came
 * before it, and only then lets the world advance; so a command sent while step k is handled is in
 * effect from step k to k+1, and the same world, agent and seed give the same run. <b>Pipelined
 * lockstep</b> ({@link #pipelined}): the controller sends step k's readings and lets the world
 * advance while the agent reasons on them; it waits for their answer at the next control step and
 * applies it there, so a command answering step k is in effect from step k+1 to k+2: one control
 * step of latency, always the same, and the run is still a function of world, agent and seed.
 *
 * <pre>{@code
 * SimWorld world = SimWorld.load(Path.of("worlds/navigation.json"));
 * try (RobotController c = new RobotController(world, ControllerConfig.defaults().withLockstep(true))) {
 *     c.start();
 *     c.runner().runFor(60);       // or runner().start() with a WorldViewer
 * }
 * }</pre>
 */
public final class RobotController implements AutoCloseable {
    private final SimWorld world;
    private final Robot robot;
    private final ControllerConfig config;
    private final DeviceSampler sampler;
    private final CommandExecutor executor;
    private final CommandInbox inbox;
    private final RobotLink link;
    private final LinkCosts costs = new LinkCosts();
    private final SimRunner runner;
    private volatile long step;
    /** Lockstep: the step sensed under the world's lock, to be sent and answered without it. */
    private Sensed sensed;
    /** A team's lockstep: the step sent by {@link #sendStep}, answered in {@link #finishStep}. */
    private Sensed sent;
    private boolean failSafeTripped;
    private volatile long failSafeTrips;
    private volatile boolean started, closed;
    /** The middleware's turn when it is in this process (lockstep over TCP), or null. */
    private volatile LockstepTurn middlewareTurn;
    /** Pipelined lockstep: the agent's answer to a step is applied at the next one. */
    private volatile boolean pipelined;
    /** Pipelined lockstep: the step sent, whose answer the next control step waits for and applies. */
    private Sensed pending;
    /** Lockstep: the last step whose answer has come (−1 before any); read on the simulation thread. */
    private long answered = -1;

    /** @throws IllegalArgumentException when the world has no robot of the configured name */
    public RobotController(SimWorld world, ControllerConfig config) {
        this(world, config, null);
    }

    /**
     * A controller whose link is {@code memory} instead of TCP (the config's address, secret and TLS
     * unused): the same frames, read by a middleware of this process on the simulation thread. Lockstep only.
     *
     * @throws IllegalArgumentException when the world has no robot of the configured name, or in real time
     */
    public RobotController(SimWorld world, ControllerConfig config, MemoryLink memory) {
        if (memory != null && !config.lockstep()) {
            // in real time the agent's thread would apply commands under the world's lock, inside the link's
            throw new IllegalArgumentException("an in-process link serves lockstep runs only");
        }
        this.world = world;
        this.config = config;
        if (world.robots().isEmpty()) {
            throw new IllegalArgumentException("world '" + world.name() + "' has no robot to control");
        }
        this.robot = config.robotName() == null ? world.robots().get(0) : world.robot(config.robotName());
        this.sampler = new DeviceSampler(robot, config.sendCameraImage());
        this.executor = new CommandExecutor(robot, sampler, world.controlStep(), config.log());
        this.inbox = new CommandInbox(world, config.nanoTime(), world::timeMs);
        this.link = new RobotLink(config, inbox, costs, memory);
        this.runner = new SimRunner(world, this::controlStep, config.lockstep() ? this::answerStep : null);
        if (config.lockstep()) {
            runner.setMode(SimRunner.Mode.FAST); // the agent's acknowledgements pace the world
        } else {
            runner.setMode(SimRunner.Mode.REAL_TIME);
            runner.setSpeedFactor(config.speedFactor());
            // A real robot's motors take a command when it comes, not at the controller's next
            // cycle: sub-millisecond response instead of up to one control step.
            inbox.applyOnReceipt(rc -> {
                executor.submit(rc);
                applyDue(world.timeMs());
            });
        }
    }

    /** Enables every device of the robot (one reading per control step) and starts the link's threads. */
    public synchronized void start() {
        if (started) {
            return;
        }
        started = true;
        List<Integer> sensors;
        synchronized (world) {
            sensors = sampler.enableAll(world.controlStep());
        }
        link.start(new Protocol.Hello(Protocol.VERSION, robot.name(), world.name(), world.controlStep(),
                config.lockstep(), sensors));
    }

    /**
     * Lockstep over TCP with the middleware in this process: after writing each step, the simulation
     * thread takes the middleware's turn ({@link LockstepTurn}: it reads the step from the
     * middleware's end of the socket and answers it) before reading the answer, so no thread wakes
     * up in a step. {@code turn} is released when this controller closes. Set it before {@link #start}.
     */
    public RobotController takeTurnsWith(LockstepTurn turn) {
        this.middlewareTurn = turn;
        return this;
    }

    /**
     * Pipelined lockstep: the world simulates the next control step while the agent reasons on the
     * last one's readings, and the agent's answer to step k is applied at step k+1 (one control step
     * of latency, fixed). Wall time per step nears the larger of the simulation's and the agent's work
     * instead of their sum, on two free cores. The same world, agent and seed still give the same run:
     * the world waits for the answer to step k before it simulates past step k+1. A single robot's
     * lockstep only (not {@link #sendStep}); the middleware's turns are not taken. Set it before the world steps.
     *
     * @throws IllegalArgumentException in real time
     */
    public RobotController pipelined(boolean on) {
        if (on && !config.lockstep()) {
            throw new IllegalArgumentException("a pipelined lockstep needs lockstep");
        }
        this.pipelined = on;
        return this;
    }

    /**
     * {@return the last step whose answer (its {@code STEP_ACK}) the simulation thread has taken, −1
     * before any} In a pipelined lockstep it lags the steps sent by one. Simulation thread only.
     */
    public long lastAnsweredStep() {
        return answered;
    }

    /**
     * Pipelined lockstep, on the simulation thread after its last control step: waits for the
     * answer to the step still pending, so that the agent has read and answered every step sent
     * before the goodbye (its commands are not applied: the world stops here). Nothing otherwise.
     */
    public void awaitLastAnswer() {
        Sensed s = pending;
        pending = null;
        if (s == null || closed) {
            return;
        }
        try {
            if (awaitAnswer(s.batch().step(), null) == CommandInbox.AckResult.ACKED) {
                inbox.takeCommands();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** {@return the runner that steps the world and calls {@link #controlStep} before each step} */
    public SimRunner runner() {
        return runner;
    }

    public SimWorld world() {
        return world;
    }

    public Robot robot() {
        return robot;
    }

    public ControllerConfig config() {
        return config;
    }

    public boolean isConnected() {
        return inbox.isConnected();
    }

    /** {@return how many connections to the middleware have come up (reconnections included)} */
    public long connections() {
        return inbox.connections();
    }

    /** {@return the last link problem (refused handshake, drop, garbage), or null} */
    public String lastProblem() {
        return link.lastProblem();
    }

    /**
     * {@return the simulated time at which a command or heartbeat of the middleware was last taken
     * in} The fail-safe counts its silence from there: a middleware that dies cannot be known dead
     * before the last of what it sent has been read.
     */
    public long lastHeardSimMs() {
        return inbox.lastHeardSimMs();
    }

    /** {@return how many times the fail-safe stopped the wheels} */
    public long failSafeTrips() {
        return failSafeTrips;
    }

    /** {@return the control steps done so far} */
    public long steps() {
        return step;
    }

    /** {@return the time spent sampling, encoding and writing steps so far} */
    public LinkCosts linkCosts() {
        return costs;
    }

    /** {@return frames discarded because the link was down or the middleware read too slowly} */
    public long droppedFrames() {
        return link.droppedFrames();
    }

    /** A lockstep step's readings, sampled at {@code now}. */
    private record Sensed(long now, Uplink.Batch batch, Uplink.StepMarker marker) {
    }

    /**
     * One control step, called with the world's lock held just before the world advances: sample
     * and send, then take the commands. In lockstep it only samples: {@link #answerStep} sends the
     * step and waits for the agent's acknowledgement without the lock. Only the simulation thread calls it.
     */
    public void controlStep(SimWorld w) {
        if (closed) {
            return;
        }
        long now = world.timeMs();
        long t0 = System.nanoTime();
        List<SensorInfo> readings = sampler.sample();
        costs.addSampling(System.nanoTime() - t0);
        long sampledMicros = config.clock().nowMicros();
        logReadings(now, readings);
        Uplink.Batch batch = new Uplink.Batch(step, now, sampledMicros, readings);
        Uplink.StepMarker marker = new Uplink.StepMarker(step, now, config.lockstep());
        if (config.lockstep()) {
            sensed = new Sensed(now, batch, marker);
            return;
        }
        List<ReceivedCommand> received = exchangeRealTime(batch, marker);
        if (received != null) {
            act(now, received);
        }
    }

    /**
     * Lockstep, after {@link #controlStep} and without the world's lock: sends the step, waits for
     * the agent's answer (a viewer still draws the world meanwhile), then applies it under the lock.
     */
    private void answerStep(SimWorld w) {
        Sensed s = sensed;
        sensed = null;
        if (s == null) {
            return;
        }
        if (pipelined) {
            answerPipelined(s);
            return;
        }
        List<ReceivedCommand> received = exchangeLockstep(s.batch(), s.marker());
        if (received == null) {
            return; // closed while waiting
        }
        synchronized (world) {
            act(s.now(), received);
        }
    }

    /**
     * Pipelined lockstep, without the world's lock: waits for the answer to the step sent at the
     * last control step, applies it now (at step k+1), then sends this step and returns, so the
     * world advances while the agent reasons on it. A drop trips the fail-safe; the step pending on
     * the dropped connection is not answered, and this one goes on the next connection.
     */
    private void answerPipelined(Sensed s) {
        try {
            List<ReceivedCommand> received = List.of();
            Sensed p = pending;
            pending = null;
            if (p != null) {
                // never the middleware's turn: it must run beside us
                switch (awaitAnswer(p.batch().step(), null)) {
                    case ACKED:
                        received = inbox.takeCommands();
                        break;
                    case CLOSED:
                        return;
                    default:
                        synchronized (world) {
                            failSafe("the link to the middleware dropped");
                        }
                }
            }
            synchronized (world) {
                act(s.now(), received); // its Applied reports go with this step's readings, as in lockstep
            }
            if (!inbox.awaitConnected()) {
                return;
            }
            link.send(out -> out.writeStep(s.batch(), s.marker()));
            pending = s;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Several robots of one world in lockstep (a team), first half of {@link #answerStep}: sends the
     * step {@link #controlStep} sensed, without waiting for the answer, so that every robot's step is
     * delivered before any agent reasons. A link that has dropped since it came up trips the
     * fail-safe instead (the robot stops and is not waited for: its team goes on).
     * {@return false when there was no step to send or no link}
     */
    public boolean sendStep() {
        Sensed s = sensed;
        sensed = null;
        if (s == null || closed) {
            return false;
        }
        if (!inbox.isConnected()) {
            if (inbox.connections() > 0) {
                synchronized (world) {
                    failSafe("the link to the middleware dropped");
                }
            }
            return false;
        }
        link.send(out -> out.writeStep(s.batch(), s.marker()));
        sent = s;
        return true;
    }

    /**
     * Second half: waits for the answer to the step {@link #sendStep} sent and applies it under the
     * world's lock (a dropped link trips the fail-safe instead). The caller steps the world after.
     */
    public void finishStep() throws InterruptedException {
        Sensed s = sent;
        sent = null;
        if (s == null) {
            return;
        }
        link.readAnswer(s.batch().step(), middlewareTurn);
        CommandInbox.AckResult ack = inbox.awaitAck(s.batch().step());
        synchronized (world) {
            if (ack == CommandInbox.AckResult.ACKED) {
                act(s.now(), inbox.takeCommands());
            } else if (ack == CommandInbox.AckResult.DROPPED) {
                failSafe("the link to the middleware dropped");
            }
        }
    }

    /** Applies the step's commands that are due. World lock held. */
    private void act(long now, List<ReceivedCommand> received) {
        for (ReceivedCommand rc : received) {
            executor.submit(rc);
        }
        applyDue(now);
        Pose p = robot.pose();
        event(() -> "pose " + p.x() + " " + p.z() + " " + p.heading());
        step++;
    }

    /** Applies what is due at {@code now} and reports each applied command to the middleware. World lock held. */
    private void applyDue(long now) {
        for (ReceivedCommand rc : executor.tick(now)) {
            failSafeTripped = false;
            event(() -> "apply " + rc.command());
            long appliedMicros = config.clock().nowMicros();
            Uplink.Applied a = new Uplink.Applied(rc.seq(), rc.command().code().code(), step, now, rc.receivedMicros(), appliedMicros);
            boolean flush = !config.lockstep(); // in lockstep it goes with the next step's data, one write less
            link.send(out -> out.writeApplied(a, flush));
        }
    }

    private List<ReceivedCommand> exchangeRealTime(Uplink.Batch batch, Uplink.StepMarker marker) {
        link.send(out -> out.writeStep(batch, marker));
        CommandInbox.Drained d = inbox.drain();
        if (d.dropped()) {
            failSafe("the link to the middleware dropped");
        }
        if (d.commands().isEmpty() && !failSafeTripped) {
            try {
                CommandInbox.Silence silence = inbox.awaitSilence(config.failSafeMs(), executor.moving());
                if (silence != null) {
                    failSafe("no command or heartbeat for " + silence.wallMs() + " ms (" + silence.simMs()
                            + " ms of simulated time)");
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return null;
            }
        }
        return d.commands();
    }

    private List<ReceivedCommand> exchangeLockstep(Uplink.Batch batch, Uplink.StepMarker marker) {
        try {
            while (true) {
                if (!inbox.awaitConnected()) {
                    return null;
                }
                link.send(out -> out.writeStep(batch, marker));
                switch (awaitAnswer(batch.step(), middlewareTurn)) {
                    case ACKED:
                        return inbox.takeCommands();
                    case CLOSED:
                        return null;
                    default:
                        synchronized (world) { // it stops the wheels: between two physics steps, as a viewer reads them
                            failSafe("the link to the middleware dropped"); // then resend this step
                        }
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }

    /**
     * Reads the answer to {@code step} (taking the middleware's turn when it is in this process) and
     * waits for its {@code STEP_ACK}, counted as the simulation thread's wait; on {@code ACKED} the
     * step is the last answered, and its commands are the inbox's to take.
     */
    private CommandInbox.AckResult awaitAnswer(long step, LockstepTurn turn) throws InterruptedException {
        long t0 = System.nanoTime();
        link.readAnswer(step, turn);
        CommandInbox.AckResult ack = inbox.awaitAck(step);
        costs.addWaiting(System.nanoTime() - t0);
        if (ack == CommandInbox.AckResult.ACKED) {
            answered = step;
        }
        return ack;
    }

    /** Stops the wheels once per silence or drop, and tells the middleware when it can. */
    private void failSafe(String reason) {
        if (failSafeTripped) {
            return;
        }
        failSafeTripped = true;
        boolean wasMoving = executor.moving();
        executor.emergencyStop();
        failSafeTrips++;
        config.log().accept("fail-safe: " + reason + (wasMoving ? "; wheels stopped" : "; wheels already stopped"));
        event(() -> "fail-safe " + reason);
        long now = world.timeMs();
        link.send(out -> out.writeFailSafe(new Uplink.FailSafe(now, reason)));
    }

    private void logReadings(long now, List<SensorInfo> readings) {
        if (config.eventLog() == null) {
            return;
        }
        StringBuilder sb = new StringBuilder();
        sb.append("step ").append(step).append(" t=").append(now);
        for (SensorInfo info : readings) {
            sb.append(' ').append(Readings.format(info));
        }
        config.eventLog().accept(sb.toString());
    }

    /** Logs an event; the text is made only when there is a log (three doubles per step cost a microsecond). */
    private void event(Supplier<String> what) {
        if (config.eventLog() != null) {
            config.eventLog().accept("step " + step + " " + what.get());
        }
    }

    /** Says goodbye to the middleware and stops the link's threads; a lockstep wait in {@link #controlStep} returns. */
    @Override
    public void close() {
        closed = true;
        inbox.close();
        link.close("controller stopped");
        LockstepTurn t = middlewareTurn;
        if (t != null) {
            t.release(); // the middleware's thread reads our goodbye
        }
    }
}
