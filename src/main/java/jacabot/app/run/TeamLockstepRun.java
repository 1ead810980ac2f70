package jacabot.app.run;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.CartagoException;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.OpTarget;
import jacabot.cartago.SimulatedClock;
import jacabot.cartago.Workspace;
import jacabot.cartago.bridge.CAgentArch;
import jacabot.cartago.bridge.CartagoEnvironment;
import jacabot.cartago.bridge.JacaStepper;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.SuspendResumeMiddleware;
import jacabot.experiments.link.LinkConfig;
import jacabot.experiments.link.LinkEvent;
import jacabot.experiments.link.StepData;
import jacabot.experiments.team.ChargerQueue;
import jacabot.experiments.team.TaskBoard;
import jacabot.robot.ControllerConfig;
import jacabot.robot.Experiment;
import jacabot.robot.link.Command;
import jacabot.robot.link.SensorInfo;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * A team of robots in one world, one agent per robot, in lockstep in one process (thesis Chapter 6,
 * multi-robot systems). Every robot has its controller and its middleware artifact
 * ({@code middleware_<robot>}) joined by in-memory frames (as {@link LockstepCoordinator#inMemory});
 * its agent is named as the robot. The agents share one stepped workspace with the team's task
 * board ({@code board}) and charger queue ({@code charger}).
 *
 * <p>Each control step: every robot's readings are sampled, then sent and delivered to its
 * middleware, in the world file's order; only then do the agents reason, together, until quiescent
 * (the barrier); then every robot's commands are answered and applied in the world file's order,
 * and the world advances one step. So a run is a pure function of the world file and the seed: the
 * same world and seed give every robot the same event log, to the byte.
 */
public final class TeamLockstepRun implements AutoCloseable {
    /** The artifacts every agent of the team shares. */
    public static final String BOARD = "board", CHARGER = "charger";
    /** Two claims' places closer than this are one cylinder on the board, metres (rough camera estimates). */
    public static final double CLAIM_RADIUS = 0.2;

    private final SimWorld world;
    private final SimulatedClock clock = new SimulatedClock();
    private final Workspace workspace;
    private final LocalMAS mas;
    private final JacaStepper stepper;
    private final AgentId host;
    private final List<TeamMember> members = new ArrayList<>();
    private final TaskBoard board;
    private final ChargerQueue charger;
    private final TeamWatch watch;
    private final List<String> linkLog = new ArrayList<>();
    private boolean stepLogs = true;
    private long cycles;
    private volatile boolean stopRequested;
    private RuntimeException failure;
    private Consumer<Long> onStep = t -> {
    };
    private RobotStepListener onAnswer = (robot, data, commands) -> {
    };

    /** What a robot's link delivered in a control step and what its agent answered. */
    @FunctionalInterface
    public interface RobotStepListener {
        void afterStep(String robot, StepData data, List<Command> commands);
    }

    /**
     * @param world every robot of it is a member of the team, in the file's order
     * @param agent the program of every robot's agent
     */
    public TeamLockstepRun(SimWorld world, AgentSource agent, long seed, PrintStream console)
            throws AslSyntaxException, CartagoException {
        this.world = world;
        workspace = Workspace.builder("main").stepped().clock(clock).console(console)
                .logger(CartagoLogger.console(console)).build();
        mas = new LocalMAS(clock::nowMillis, console, seed);
        mas.setEnvironment(new CartagoEnvironment(workspace), List.of());
        stepper = new JacaStepper(mas, workspace);
        host = workspace.join("runner", new ArtifactObserverAdapter());
        ArtifactId boardId = workspace.createArtifact(BOARD, TaskBoard.class.getName(), CLAIM_RADIUS);
        board = workspace.artifactObject(boardId, TaskBoard.class).orElseThrow();
        ArtifactId chargerId = workspace.createArtifact(CHARGER, ChargerQueue.class.getName());
        charger = workspace.artifactObject(chargerId, ChargerQueue.class).orElseThrow();
        AslParser parser = agent.parser();
        for (Robot robot : world.robots()) {
            String name = robot.name();
            // made before the agents start, so that each one's !init finds its own (thesis Chapter 4 §5)
            ArtifactId id = workspace.createArtifact("middleware_" + name, SuspendResumeMiddleware.class.getName(), 0, "lockstep");
            MiddlewareArtifact middleware = workspace.artifactObject(id, MiddlewareArtifact.class).orElseThrow();
            AgentProgram program = WorldBeliefs.inject(agent.parse(parser), world.spec(), Experiment.SUSPEND_RESUME);
            List<Literal> goals = program.goals();
            FailureWatch failures = new FailureWatch(goals);
            mas.createAgent(name, program, parser, CAgentArch::new)
                    .setPlanListener((event, plan) -> failures.planSelected(event, clock.nowMillis()));
            members.add(new TeamMember(name, id, middleware, failures, goals));
        }
        watch = new TeamWatch(world, board, charger, members.stream().map(TeamMember::robot).toList());
    }

    /** Whether every robot's event log keeps a line per step (readings, commands, pose); on by default. */
    public TeamLockstepRun stepLogs(boolean keep) {
        this.stepLogs = keep;
        return this;
    }

    /** Called after each control step with the simulated time (progress lines). */
    public void onStep(Consumer<Long> listener) {
        this.onStep = listener;
    }

    /**
     * Called for each robot after each control step, in the world file's order, with its readings
     * and the commands going to it: the agents are idle, the world not yet stepped (step logs, the
     * inspector). Only reads, so the run is the same with or without it.
     */
    public void onAnswer(RobotStepListener listener) {
        this.onAnswer = listener;
    }

    public SimWorld world() {
        return world;
    }

    public LocalMAS mas() {
        return mas;
    }

    /** {@return the team's workspace (read it, e.g. the inspector's artifacts panel; the run drives it)} */
    public Workspace workspace() {
        return workspace;
    }

    public long cycles() {
        return cycles;
    }

    /** {@return the team's robots, in the world file's order} */
    public List<String> robots() {
        return members.stream().map(TeamMember::robot).toList();
    }

    /** {@return what the run's watch saw: claims, double claims, charger waits} */
    public TeamWatch watch() {
        return watch;
    }

    /** {@return the team's task board (read it between two steps, e.g. in {@link #onStep})} */
    public TaskBoard board() {
        return board;
    }

    /** {@return robot {@code robot}'s event log: its controller's lines and its agent side's, one per step} */
    public List<String> eventLog(String robot) {
        return members.stream().filter(m -> m.robot().equals(robot)).findFirst().orElseThrow().eventLog();
    }

    /** {@return the first agent that failed at its job and why, e.g. "khepera2: no plan for !start"} */
    public Optional<String> agentFailure() {
        for (TeamMember m : members) {
            Optional<String> v = m.failures().verdict();
            if (v.isPresent()) {
                return Optional.of(m.robot() + ": " + v.get());
            }
        }
        return Optional.empty();
    }

    /** Ends a run in progress after the current step. */
    public void stop() {
        stopRequested = true;
    }

    @Override
    public void close() {
        members.forEach(TeamMember::closeLink);
        workspace.close();
    }

    /**
     * Runs {@code seconds} of simulated time (less when an agent fails at its job or {@link #stop}).
     *
     * @throws IllegalStateException when the agent side fails
     */
    public void runFor(double seconds) {
        for (TeamMember m : members) {
            ControllerConfig cc = ControllerConfig.defaults().withRobot(m.robot()).withLockstep(true).withLog(linkLog::add);
            if (stepLogs) {
                cc = cc.withEventLog(m.eventLog()::add);
            }
            m.connect(InProcessLink.inMemory(world, cc, LinkConfig.defaults().withLog(linkLog::add)));
        }
        SimRunner runner = new SimRunner(world, w -> members.forEach(m -> m.link().controller().controlStep(w)), this::step);
        runner.setMode(SimRunner.Mode.FAST);
        long end = world.timeMs() + Math.round(seconds * 1000);
        while (world.timeMs() < end && !stopRequested && failure == null) {
            runner.stepOnce();
        }
        if (failure != null) {
            throw failure;
        }
    }

    /** One team step, without the world's lock: deliver every robot's step, reason once, answer every robot. */
    private void step(SimWorld w) {
        try {
            for (TeamMember m : members) {
                m.link().controller().sendStep(); // in memory: the robot's frames are read before this returns
            }
            long now = w.timeMs();
            if (now > clock.nowMillis()) {
                clock.advance(now - clock.nowMillis());
            }
            for (TeamMember m : members) {
                StepData data = m.takeStep();
                if (data != null && !mas.isStopped()) {
                    workspace.execOpInline(host, OpTarget.id(m.middlewareId()), "deliverStep", new Object[] {data}, outcome -> {
                    });
                }
            }
            if (!mas.isStopped()) {
                cycles += stepper.runUntilQuiescent(LockstepRun.CYCLES_PER_STEP * members.size());
                for (TeamMember m : members) {
                    m.firstReasoningDone(mas);
                }
            }
            for (TeamMember m : members) {
                m.answer(stepLogs, onAnswer);
            }
            for (TeamMember m : members) {
                m.link().controller().finishStep();
            }
            watch.afterStep(now);
            if (agentFailure().isPresent() || mas.isStopped()) {
                stopRequested = true;
            }
            onStep.accept(now);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            stopRequested = true;
        } catch (RuntimeException e) {
            failure = e;
        }
    }

    /** The middleware end of a robot's link: collects a step's readings until its marker. */
    static final class StepCollector implements Consumer<LinkEvent> {
        private final List<SensorInfo> readings = new ArrayList<>();
        private StepData pending;

        @Override
        public void accept(LinkEvent e) {
            if (e instanceof LinkEvent.Connected) {
                readings.clear();
            } else if (e instanceof LinkEvent.Reading r) {
                readings.add(r.info());
            } else if (e instanceof LinkEvent.StepMarker m) {
                pending = new StepData(m.step(), m.simTimeMs(), List.copyOf(readings));
                readings.clear();
            }
        }

        StepData take() {
            StepData d = pending;
            pending = null;
            return d;
        }
    }
}
