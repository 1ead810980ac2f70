package jacabot.app.run;
import jacabot.experiments.link.LatencyStats;
import jacabot.experiments.link.LinkTimings;
import jacabot.experiments.link.StepData;
import jacabot.experiments.link.MiddlewareLink;
import jacabot.experiments.link.LinkEvent;
import jacabot.experiments.link.LinkConfig;

import jacabot.robot.ControllerConfig;
import jacabot.robot.link.Readings;
import jacabot.robot.link.Command;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.SensorInfo;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * Runs a world in lockstep with an agent side, over the real socket protocol (an
 * {@link InProcessLink}), or with its frames in memory ({@link #inMemory}). Each control step: the controller sends the step's readings and a step
 * marker; the coordinator hands them to the {@link AgentSide} (deliver, reason until quiescent,
 * collect the actions), sends the returned commands and {@code STEP_ACK}; only then does the world
 * advance. Same world, agent and seed ⇒ the same run, to the byte of both event logs.
 *
 * <pre>{@code
 * var run = new LockstepCoordinator(SimWorld.load(path), "khepera", data -> {
 *     clock.advance(data.simTimeMs() - clock.nowMillis()); // the one SimulatedClock follows the world
 *     artifact.deliver(data.readings());
 *     mas.runUntilQuiescent(1000);
 *     return artifact.takeCommands();
 * }).runFor(30);
 * }</pre>
 */
public final class LockstepCoordinator {
    /** The agent platform's side of one step. */
    @FunctionalInterface
    public interface AgentSide {
        /** Delivers the step's readings, runs the agents until quiescent, {@return the commands to send} */
        List<Command> step(StepData data) throws Exception;
    }

    /** What a run leaves: its steps, the controller's and the agent side's event logs, the timings. */
    public record Result(long steps, List<String> controllerLog, List<String> agentLog, LatencyStats response,
                         List<String> linkLog, LinkCosts controllerCosts, LinkCosts middlewareCosts, LinkTimings timings) {
        /** {@return both logs as one text, controller first (what two runs must agree on)} */
        public String eventLog() {
            return String.join("\n", controllerLog) + "\n--\n" + String.join("\n", agentLog) + "\n";
        }
    }

    /** Safety net: a controller silent this long is broken, not slow. */
    private static final long SILENCE_LIMIT_SECONDS = 60;

    private final SimWorld world;
    private final String robotName;
    private final AgentSide agent;
    private boolean stepLogs = true;
    private Consumer<String> controllerLogSink;
    private int port;
    private boolean remote;
    private boolean inMemory;
    private boolean turns;
    private boolean pipeline;
    private Runnable afterAnswer = () -> {
    };
    /** Pipelined: the step whose answer ends the run (a failed agent's), −1 while none. */
    private volatile long endStep = -1;
    /** The step the agent side is answering (its own thread's). */
    private volatile long answering;
    /** The CPU time of the simulation thread and of the thread that ran the agent side, at the run's end (−1: not read). */
    private volatile long simulationCpu = -1, agentSideCpu = -1, simulationSystem = -1, agentSideSystem = -1;
    private volatile MiddlewareLink remoteLink;
    private volatile InProcessLink running;
    private volatile boolean stopRequested;

    /** @param robotName the robot to control, null for the world's first */
    public LockstepCoordinator(SimWorld world, String robotName, AgentSide agent) {
        this.world = world;
        this.robotName = robotName;
        this.agent = agent;
    }

    /**
     * Whether to keep a line per step on both sides (readings, commands, poses): what replays are
     * compared on. On by default; formatting them is a tenth of a benchmark run's time.
     */
    public LockstepCoordinator stepLogs(boolean keep) {
        this.stepLogs = keep;
        return this;
    }

    /**
     * Streams the controller's event log to {@code sink} (e.g. a file) instead of keeping it, and
     * keeps no agent-side log: a long run's memory stays flat. {@link Result#controllerLog()} is then empty.
     */
    public LockstepCoordinator controllerLogTo(Consumer<String> sink) {
        this.controllerLogSink = sink;
        return this;
    }

    /**
     * Runs {@code hook} on the agent side's thread after each step's answer has gone to the
     * controller, before the next step reaches the agents: they are idle, and the world may be
     * advancing meanwhile, so it reads the agents, not the world (the step log's capture of the mind).
     */
    public LockstepCoordinator afterAnswer(Runnable hook) {
        this.afterAnswer = hook;
        return this;
    }

    /** Listens on {@code port} instead of a free one. */
    public LockstepCoordinator port(int listenPort) {
        this.port = listenPort;
        return this;
    }

    /**
     * The two-process set-up: the controller is another process ({@code jacabot controller
     * --lockstep}) that connects to {@link #port} with the user's link secret; this side answers its
     * steps exactly as for an in-process controller, so both runs are the same run. The world here
     * only gives the spec; it is not stepped. {@link Result#controllerLog()} is then empty (the
     * controller writes its own: {@code jacabot controller --event-log FILE}).
     */
    public LockstepCoordinator remoteController(boolean on) {
        this.remote = on;
        return this;
    }

    /**
     * The frames go through memory instead of a loopback socket ({@link InProcessLink#inMemory}), and
     * the agent side answers each step on the simulation thread: the same run, to the byte of both
     * event logs, without the socket's system calls and thread hand-offs (sweeps). As over the socket,
     * the agent's turn runs without the world's lock. Off by default: single runs keep the thesis' socket.
     */
    public LockstepCoordinator inMemory(boolean on) {
        this.inMemory = on;
        return this;
    }

    /**
     * Over the socket, the simulation thread also takes the middleware's turns
     * ({@link InProcessLink#start(SimWorld, ControllerConfig, LinkConfig, int, boolean)}): no thread
     * wakes up in a step. Off by default: on this project's loaded machine it was measured slower
     * (docs/performance.md §9); the same run to the byte either way.
     */
    public LockstepCoordinator takeTurns(boolean on) {
        this.turns = on;
        return this;
    }

    /**
     * A pipelined lockstep ({@link jacabot.robot.RobotController#pipelined}): the world simulates
     * the next control step while the agent reasons on the last one's readings, and the agent's
     * answer to step k is applied at step k+1. Still a function of world, agent and seed, but not
     * the same run as the plain lockstep's (one control step of latency). Off by default; not with
     * {@link #remoteController} (the controller's own option there) nor a team.
     */
    public LockstepCoordinator pipeline(boolean on) {
        this.pipeline = on;
        return this;
    }

    /**
     * {@return the CPU time in ns of the simulation thread and of the thread the agent side ran on
     * (the middleware's reading thread over the socket), at the run's end; −1 where not known} Two
     * such numbers say what a step costs whatever the machine's load: their sum in lockstep, at best
     * the larger of them in a pipelined lockstep. Then the same threads' system time (the kernel's
     * share of that CPU: over a socket, the link's system calls, sleeps and wake-ups).
     */
    public long[] threadCpuNanos() {
        return new long[] {simulationCpu, agentSideCpu, simulationSystem, agentSideSystem};
    }

    /** {@return with {@link #remoteController}, the port the agent side listens on once it does (0 before)} */
    public int listeningPort() {
        MiddlewareLink m = remoteLink;
        return m != null ? m.port() : 0;
    }

    /**
     * Ends the run after the step in progress, from the agent side's own step (a failed agent): the
     * world stops advancing and the controller says goodbye; a remote controller's link is closed.
     */
    public void endAfterThisStep() {
        if (pipeline && !remote) {
            // the world is a step ahead of the agent: it ends once it has taken this step's answer,
            // whenever this thread gets here
            if (endStep < 0) {
                endStep = answering;
            }
            return;
        }
        stopRequested = true;
        MiddlewareLink m = remoteLink;
        if (m != null) {
            new Thread(m::close, "lockstep-end").start();
        }
    }

    /** Ends the run at the current step (e.g. on SIGTERM): {@link #runFor} returns what it has. */
    public void stop() {
        stopRequested = true;
        InProcessLink l = running;
        if (l != null) {
            l.controller().close();
        }
        MiddlewareLink m = remoteLink;
        if (m != null) {
            m.close();
        }
    }

    /**
     * Runs {@code seconds} of simulated time.
     *
     * @throws IOException when the link cannot be opened
     * @throws IllegalStateException when the agent side fails or the controller falls silent
     */
    public Result runFor(double seconds) throws IOException, InterruptedException {
        List<String> controllerLog = Collections.synchronizedList(new ArrayList<>());
        List<String> agentLog = Collections.synchronizedList(new ArrayList<>());
        List<String> linkLog = Collections.synchronizedList(new ArrayList<>());
        Consumer<String> log = linkLog::add;
        if (remote) {
            if (pipeline) {
                throw new IllegalStateException("a pipelined lockstep is the controller's option when it is another process");
            }
            return runRemote(seconds, agentLog, linkLog);
        }
        ControllerConfig cc = ControllerConfig.defaults().withRobot(robotName).withLockstep(true).withLog(log);
        if (stepLogs) {
            cc = cc.withEventLog(controllerLogSink != null ? controllerLogSink : controllerLog::add);
        }
        LinkConfig lc = LinkConfig.defaults().withLog(log);
        try (InProcessLink link = inMemory ? InProcessLink.inMemory(world, cc, lc) : InProcessLink.start(world, cc, lc, port, turns && !pipeline)) {
            running = link;
            link.controller().pipelined(pipeline);
            if (stopRequested) {
                link.controller().close();
            }
            Server server = new Server(link.middleware(), stepLogs && controllerLogSink == null ? agentLog : null);
            link.middleware().handOver(server);
            Throwable[] simFailure = new Throwable[1];
            Thread simulation = new Thread(() -> {
                try {
                    // a control step at a time, so that stop() (SIGTERM) ends the run at the next step
                    long end = world.timeMs() + Math.round(seconds * 1000);
                    long chunk = world.controlStep();
                    while (world.timeMs() < end && !stopRequested && !endAnswered(link)) {
                        link.controller().runner().runFor(Math.min(chunk, end - world.timeMs()) / 1000.0);
                    }
                    link.controller().awaitLastAnswer(); // pipelined: the agent answers every step it was sent
                } catch (RuntimeException | Error e) {
                    simFailure[0] = e;
                } finally {
                    simulationCpu = threadCpu();
                    simulationSystem = threadSystem(simulationCpu);
                    link.controller().close(); // says goodbye: the agent side's loop ends
                }
            }, "lockstep-simulation");
            simulation.setDaemon(true);
            simulation.start();
            try {
                server.awaitEnd();
            } finally {
                link.controller().close();
                simulation.join(TimeUnit.SECONDS.toMillis(SILENCE_LIMIT_SECONDS));
            }
            if (simFailure[0] != null) {
                throw new IllegalStateException("the simulation failed: " + simFailure[0], simFailure[0]);
            }
            return new Result(server.steps, List.copyOf(controllerLog), List.copyOf(agentLog),
                    link.middleware().timings().response(), List.copyOf(linkLog), link.controller().linkCosts(),
                    link.middleware().costs(), link.middleware().timings());
        }
    }

    /** Pipelined: whether the controller has taken the answer that ends the run (so the same step whatever the timing). */
    private boolean endAnswered(InProcessLink link) {
        long e = endStep;
        return e >= 0 && link.controller().lastAnsweredStep() >= e;
    }

    /** {@link #runFor} with the controller in another process: until its goodbye or {@code seconds} of steps. */
    private Result runRemote(double seconds, List<String> agentLog, List<String> linkLog) throws IOException, InterruptedException {
        try (MiddlewareLink link = MiddlewareLink.open(LinkConfig.defaults().withPort(port).withLog(linkLog::add))) {
            remoteLink = link;
            if (stopRequested) {
                link.close();
            }
            Server server = new Server(link, stepLogs ? agentLog : null);
            server.endAt = Math.round(seconds * 1000);
            link.handOver(server);
            try {
                server.awaitEnd();
            } finally {
                remoteLink = null;
            }
            return new Result(server.steps, List.of(), List.copyOf(agentLog), link.timings().response(),
                    List.copyOf(linkLog), new LinkCosts(), link.costs(), link.timings());
        }
    }

    /**
     * The agent side, run where the link reads the step: on the simulation thread, which takes the
     * middleware's turn over the in-process socket ({@link InProcessLink}) or reads the in-memory
     * link; on the link's reading thread for a remote controller. It collects a step's readings,
     * calls the agent at its marker, answers with the commands and the acknowledgement in one write.
     */
    private final class Server implements Consumer<LinkEvent> {
        private final MiddlewareLink link;
        private final List<String> agentLog;
        private final List<SensorInfo> readings = new ArrayList<>();
        private final CountDownLatch end = new CountDownLatch(1);
        private final SilenceWatch silence = new SilenceWatch(SILENCE_LIMIT_SECONDS);
        private volatile RuntimeException failure;
        private volatile long steps;
        private volatile boolean connectedOnce;
        /** A remote controller's run ends after the step before this simulated time (ms); −1: at its goodbye. */
        private long endAt = -1;
        private volatile boolean answeredLast;

        Server(MiddlewareLink link, List<String> agentLog) {
            this.link = link;
            this.agentLog = agentLog;
        }

        @Override
        public void accept(LinkEvent e) {
            silence.heard();
            if (end.getCount() == 0) {
                return;
            }
            try {
                if (e instanceof LinkEvent.Connected) {
                    connectedOnce = true;
                    readings.clear();
                } else if (e instanceof LinkEvent.Reading) {
                    readings.add(((LinkEvent.Reading) e).info());
                } else if (e instanceof LinkEvent.StepMarker && answeredLast) {
                    end.countDown(); // a controller that runs on past this side's duration: it is cut off here
                } else if (e instanceof LinkEvent.StepMarker) {
                    LinkEvent.StepMarker m = (LinkEvent.StepMarker) e;
                    answering = m.step();
                    List<Command> commands = callAgent(new StepData(m.step(), m.simTimeMs(), readings));
                    if (agentLog != null) {
                        agentLog.add(describe(m, readings, commands));
                    }
                    readings.clear();
                    link.answerStep(commands, m.step());
                    afterAnswer.run();
                    steps++;
                    if (endAt >= 0 && m.simTimeMs() + link.robot().controlStepMs() >= endAt) {
                        // the same steps as an in-process run of this duration; the answer is still on
                        // its way, so wait for the controller's goodbye rather than close at once
                        answeredLast = true;
                    }
                } else if (e instanceof LinkEvent.Disconnected && connectedOnce) {
                    agentSideCpu = threadCpu();
                    agentSideSystem = threadSystem(agentSideCpu);
                    end.countDown(); // the controller said goodbye (or dropped: nothing more will come)
                }
            } catch (RuntimeException | Error failed) {
                // reported to the caller of runFor; the reading thread must not die with it
                failure = failed instanceof RuntimeException r ? r
                        : new IllegalStateException("the agent side failed: " + failed, failed);
                end.countDown();
            }
        }

        /** Waits for the controller's goodbye; rethrows the agent side's failure. */
        void awaitEnd() throws InterruptedException {
            while (!end.await(1, TimeUnit.SECONDS)) {
                if (!connectedOnce && endAt >= 0) {
                    continue; // waiting for the other process's controller, as long as it takes
                }
                if (silence.tooLong()) {
                    throw new IllegalStateException("no data from the controller for " + SILENCE_LIMIT_SECONDS + " s");
                }
            }
            if (failure != null) {
                throw failure;
            }
        }
    }

    private static long threadCpu() {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        return threads.isCurrentThreadCpuTimeSupported() ? threads.getCurrentThreadCpuTime() : -1;
    }

    /** {@return the calling thread's system time, given its CPU time {@code cpu} read just before; −1 where not known} */
    private static long threadSystem(long cpu) {
        return cpu < 0 ? -1 : Math.max(0, cpu - ManagementFactory.getThreadMXBean().getCurrentThreadUserTime());
    }

    private List<Command> callAgent(StepData data) {
        try {
            List<Command> commands = agent.step(data);
            return commands == null ? List.of() : commands;
        } catch (Exception e) {
            throw new IllegalStateException("the agent side failed at step " + data.step() + ": " + e.getMessage(), e);
        }
    }

    private static String describe(LinkEvent.StepMarker m, List<SensorInfo> readings, List<Command> commands) {
        return describe(m.step(), m.simTimeMs(), readings, commands);
    }

    /** {@return the agent side's line of a step in the event log: its readings and the commands answered} */
    static String describe(long step, long simTimeMs, List<SensorInfo> readings, List<Command> commands) {
        StringBuilder sb = new StringBuilder("step ").append(step).append(" t=").append(simTimeMs);
        for (SensorInfo info : readings) {
            sb.append(' ').append(Readings.format(info));
        }
        sb.append(" -> ").append(commands);
        return sb.toString();
    }
}
