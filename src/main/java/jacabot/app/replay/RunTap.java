package jacabot.app.replay;

import jacabot.app.inspector.MindWatch;
import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.RobotView;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.robot.link.Command;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.robot.Robot;
import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

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
    private volatile jacabot.app.inspector.Debugger debugger;

    private RunTap(LockstepRun run, Inspector inspector, StepLog.Writer log) {
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
                    w.robots().get(0).name(), agentFile, start);
            log = new StepLog.Writer(outDir.resolve(StepLog.FILE), header);
            if (inspector != null) {
                archive(inspector, log, outDir.resolve(StepLog.FILE), header);
            }
        }
        if (inspector != null) {
            inspector.world(start);
        }
        return new RunTap(run, inspector, log);
    }

    /** The inspector reads the robot agent's past, beyond its memory, from the step log being written. */
    static void archive(Inspector inspector, StepLog.Writer log, Path file, StepLog.Header header) {
        var archive = StepArchive.live(file, header);
        log.onChunk(archive::add);
        inspector.add("robot").archive(archive);
    }

    private void afterStep(jacabot.experiments.link.StepData data, List<Command> commands) {
        var text = new ArrayList<String>(commands.size());
        commands.forEach(c -> text.add(c.toString()));
        if (!commands.isEmpty()) {
            lastCommands = text;
        }
        MindState mind = watch == null ? null : watch.capture();
        if (log != null) {
            List<jacabot.sim.engine.ObjectState> objects;
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

    /** Halts the run on {@code d}'s breakpoints, after the step is logged and shown. {@return this} */
    public RunTap debugger(jacabot.app.inspector.Debugger d) {
        this.debugger = d;
        return this;
    }

    /** As {@link #debugger(jacabot.app.inspector.Debugger)}, also driven from {@code inspector}'s page (if not null). */
    public RunTap debugger(Inspector inspector, jacabot.app.inspector.Debugger d) {
        if (inspector != null) {
            inspector.debugger(d);
        }
        return debugger(d);
    }

    private RobotView robotView() {
        return view(world, robot, lastCommands);
    }

    /** {@return the first robot's body now, without commands (a real-time run sends them over its socket)} */
    public static java.util.function.Supplier<RobotView> robotView(SimWorld world) {
        Robot r = world.robots().get(0);
        return () -> view(world, r, List.of());
    }

    private static RobotView view(SimWorld world, Robot robot, List<String> commands) {
        synchronized (world) {
            var p = robot.pose();
            var placed = new ArrayList<RobotView.Placed>();
            for (jacabot.sim.engine.ObjectState o : world.supervisor().objects()) {
                if (o.movable()) {
                    placed.add(new RobotView.Placed(o.id(), StepLog.round(o.pose().x()), StepLog.round(o.pose().z()),
                            StepLog.round(o.pose().heading()), o.carriedBy()));
                }
            }
            return new RobotView(world.timeMs(), p.x(), p.z(), p.heading(),
                    robot.hasBattery() ? robot.getBattery().energy() : null, robot.getWheels().getLeftSpeed(),
                    robot.getWheels().getRightSpeed(), commands, placed);
        }
    }

    @Override
    public void close() throws IOException {
        if (log != null) {
            log.close();
        }
    }
}
