package jacabot.app.replay;

import jacabot.app.inspector.Debugger;
import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindProbe;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.MindWatch;
import jacabot.app.inspector.RobotView;
import jacabot.app.run.LockstepRun;
import jacabot.app.run.WorldAtStep;
import jacabot.experiments.link.StepData;
import jacabot.robot.Experiment;
import jacabot.robot.link.Command;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.robot.Robot;
import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Taps a lockstep run after each control step, while the agent is idle: captures the robot
 * agent's mind once and hands it to the inspector (if any) and to the step log (if any). Only
 * reads the agent and the world, so the run itself is the same with or without it. The step log's
 * world is read on the simulation thread at each step ({@link WorldAtStep}), so that a pipelined
 * run's log is the world at the step too; without a debugger the mind is captured after the
 * step's answer has gone, while the world simulates the next step.
 */
public final class RunTap implements Closeable {
    private final RobotTap robot;
    private final MindWatch watch;
    private volatile Debugger debugger;
    private final LockstepRun run;
    private StepLog.Header header;
    private StepLog.Writer log;
    private WorldAtStep<RobotTap.Seen> seen;
    /** The step answered and not yet recorded: the agent side's, or at the end {@link #close}'s, to take once. */
    private final AtomicReference<Pending> pending = new AtomicReference<>();

    private record Pending(StepData data, List<Command> commands, RobotTap.Seen seen) {
    }

    private RunTap(LockstepRun run, Inspector inspector, StepLog.Writer log) {
        this.run = run;
        SimWorld world = run.world();
        // a robot programmed by several agents: the first one's mind (the task agent's)
        this.robot = new RobotTap(world, world.robots().get(0), run.mas().agent(run.agentNames().get(0)), inspector, log);
        this.watch = robot.watch();
        run.onCommands(this::afterStep);
        run.afterAnswer(this::afterAnswer);
    }

    /**
     * Taps {@code run}; call before it runs.
     *
     * @param inspector the inspector, or null
     * @param outDir where {@value StepLog#FILE} goes, or null for no step log
     */
    public static RunTap attach(LockstepRun run, Inspector inspector, Path outDir, Experiment experiment, String agentFile)
            throws IOException {
        StepLog.Writer log = null;
        SimWorld w = run.world();
        WorldSnapshot start = w.snapshot();
        if (outDir != null) {
            var header = new StepLog.Header(StepLog.FORMAT, experiment.id(), w.name(), w.seed(), w.controlStep(),
                    w.robots().get(0).name(), agentFile, start,
                    run.mas().agent("robot") == null ? null : MindProbe.planTexts(run.mas().agent("robot")));
            log = RobotTap.open(outDir.resolve(StepLog.FILE), header, inspector, "robot");
        }
        if (inspector != null) {
            inspector.world(start);
            inspector.workspace(ArtifactsView.of(run.workspace()));
        }
        var tap = new RunTap(run, inspector, log);
        tap.header = log == null ? null : log.header();
        tap.log = log;
        tap.seen = log == null ? null : WorldAtStep.attach(w, tap.robot::see);
        return tap;
    }

    /** {@return the step log's header, or null without a step log} */
    public StepLog.Header header() {
        return header;
    }

    /**
     * Hands every step of the step log, as read back, to {@code sink} on the log's writer thread
     * (null, or no step log: nothing). Call before the run; {@code sink} is complete after
     * {@link #close()}.
     */
    public void onSteps(Consumer<StepLog.Step> sink) {
        if (log != null && sink != null) {
            log.onStep(sink);
        }
    }

    /** The inspector reads the robot agent's past, beyond its memory, from the step log being written. */
    static void archive(Inspector inspector, StepLog.Writer log, Path file, StepLog.Header header) {
        RobotTap.archive(inspector, log, file, header, "robot");
    }

    private void afterStep(StepData data, List<Command> commands) {
        robot.note(data, commands);
        RobotTap.Seen world = seen == null ? null : seen.take(data.simTimeMs());
        var d = debugger;
        if (d == null) { // nothing waits for the mind: captured once the answer has gone
            pending.set(new Pending(data, commands, world));
            return;
        }
        MindState mind = robot.record(data, commands, world);
        if (mind != null) {
            d.afterStep(mind); // may halt here, the world waiting with the agent
        }
    }

    private void afterAnswer() {
        Pending p = pending.getAndSet(null);
        if (p != null) {
            robot.record(p.data(), p.commands(), p.seen());
        }
    }

    /**
     * Halts the run on {@code d}'s breakpoints, after the step is logged and shown, and before a
     * reasoning cycle when {@code d} steps one cycle. {@return this}
     */
    public RunTap debugger(Debugger d) {
        this.debugger = d;
        if (d != null && watch != null) {
            run.beforeCycle(a -> {
                if (watch.watches(a)) {
                    d.beforeCycle(watch::peekBeforeCycle);
                }
            });
        }
        return this;
    }

    /** As {@link #debugger(Debugger)}, also driven from {@code inspector}'s page (if not null). */
    public RunTap debugger(Inspector inspector, Debugger d) {
        if (inspector != null) {
            inspector.debugger(d);
        }
        return debugger(d);
    }

    /** {@return the first robot's body now, without commands (a real-time run sends them over its socket)} */
    public static Supplier<RobotView> robotView(SimWorld world) {
        Robot r = world.robots().get(0);
        var boxesAtStart = RobotTap.fixedBoxes(world);
        return () -> RobotTap.view(world, r, List.of(), List.of(), boxesAtStart);
    }

    @Override
    public void close() throws IOException {
        afterAnswer(); // a run stopped between a step and its answer
        if (seen != null) {
            seen.detach();
        }
        robot.close();
    }
}
