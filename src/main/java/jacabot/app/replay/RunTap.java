package jacabot.app.replay;

import jacabot.app.inspector.Debugger;
import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindProbe;
import jacabot.app.inspector.MindWatch;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.RobotView;
import jacabot.app.run.LockstepRun;
import jacabot.experiments.link.StepData;
import jacabot.robot.Experiment;
import jacabot.robot.link.Command;
import jacabot.robot.link.SensorInfo;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.robot.Robot;
import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;

/**
 * Taps a lockstep run after each control step, while the agent is idle: captures the robot
 * agent's mind once and hands it to the inspector (if any) and to the step log (if any). Only
 * reads the agent and the world, so the run itself is the same with or without it.
 */
public final class RunTap implements Closeable {
    private final SimWorld world;
    private final Robot robot;
    private final MindWatch watch;
    private final StepLog.Writer log;
    private volatile List<String> lastCommands = List.of();
    private volatile List<SensorInfo> lastReadings = List.of();
    private volatile Debugger debugger;
    private final LockstepRun run;
    private StepLog.Header header;

    private RunTap(LockstepRun run, Inspector inspector, StepLog.Writer log) {
        this.run = run;
        this.world = run.world();
        this.robot = world.robots().get(0);
        this.log = log;
        // a robot programmed by several agents: the first one's mind (the task agent's)
        var agent = run.mas().agent(run.agentNames().get(0));
        this.watch = agent == null ? null : MindWatch.attach(inspector, agent, this::robotView);
        run.onCommands(this::afterStep);
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
            log = new StepLog.Writer(outDir.resolve(StepLog.FILE), header);
            if (inspector != null) {
                archive(inspector, log, outDir.resolve(StepLog.FILE), header);
            }
        }
        if (inspector != null) {
            inspector.world(start);
        }
        var tap = new RunTap(run, inspector, log);
        tap.header = log == null ? null : log.header();
        return tap;
    }

    /** {@return the step log's header, or null without a step log} */
    public StepLog.Header header() {
        return header;
    }

    /** The inspector reads the robot agent's past, beyond its memory, from the step log being written. */
    static void archive(Inspector inspector, StepLog.Writer log, Path file, StepLog.Header header) {
        var archive = StepArchive.live(file, header);
        log.onChunk(archive::add);
        inspector.add("robot").archive(archive);
    }

    private void afterStep(StepData data, List<Command> commands) {
        var text = new ArrayList<String>(commands.size());
        commands.forEach(c -> text.add(c.toString()));
        if (!commands.isEmpty()) {
            lastCommands = text;
        }
        lastReadings = data.readings();
        MindState mind = watch == null ? null : watch.capture();
        if (log != null) {
            List<ObjectState> objects;
            StepLog.Body body;
            synchronized (world) {
                // not world.snapshot(): it copies the whole trajectory, every step
                objects = world.supervisor().objects();
                var p = robot.pose();
                body = new StepLog.Body(p.x(), p.z(), p.heading(), robot.hasBattery() ? robot.getBattery().energy() : null,
                        robot.getWheels().getLeftSpeed(), robot.getWheels().getRightSpeed(),
                        robot.hasGripper() ? robot.getGripper().heldObject() : null, robot.contactTime());
            }
            log.step(data.simTimeMs(), body, commands, data.readings(), mind, objects);
        }
        var d = debugger;
        if (d != null && mind != null) {
            d.afterStep(mind); // may halt here, the world waiting with the agent
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

    private RobotView robotView() {
        var readings = new ArrayList<String>();
        lastReadings.forEach(r -> readings.add(StepLog.reading(r)));
        return view(world, robot, lastCommands, readings);
    }

    /** {@return the first robot's body now, without commands (a real-time run sends them over its socket)} */
    public static Supplier<RobotView> robotView(SimWorld world) {
        Robot r = world.robots().get(0);
        return () -> view(world, r, List.of(), List.of());
    }

    private static RobotView view(SimWorld world, Robot robot, List<String> commands, List<String> readings) {
        synchronized (world) {
            var p = robot.pose();
            var placed = new ArrayList<RobotView.Placed>();
            for (ObjectState o : world.supervisor().objects()) {
                if (o.movable()) {
                    placed.add(new RobotView.Placed(o.id(), StepLog.round(o.pose().x()), StepLog.round(o.pose().z()),
                            StepLog.round(o.pose().heading()), o.carriedBy()));
                }
            }
            return new RobotView(world.timeMs(), p.x(), p.z(), p.heading(),
                    robot.hasBattery() ? robot.getBattery().energy() : null, robot.getWheels().getLeftSpeed(),
                    robot.getWheels().getRightSpeed(), commands, placed, readings);
        }
    }

    @Override
    public void close() throws IOException {
        if (log != null) {
            log.close();
        }
    }
}
