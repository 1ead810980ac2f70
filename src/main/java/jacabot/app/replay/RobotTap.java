package jacabot.app.replay;

import jacabot.agent.semantics.Agent;
import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.MindWatch;
import jacabot.app.inspector.RobotView;
import jacabot.experiments.link.StepData;
import jacabot.robot.link.Command;
import jacabot.robot.link.SensorInfo;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.geom.Pose;
import jacabot.sim.robot.Robot;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * One robot's part of a tap on a lockstep run, after each control step while its agent is idle:
 * the agent's mind captured once, handed to the inspector (if any) and, with the robot's body,
 * the commands and the readings, to the robot's step log (if any). A run of one robot has one
 * ({@link RunTap}), a team's run one per robot ({@link TeamTap}).
 */
final class RobotTap {
    private final SimWorld world;
    private final Robot robot;
    private final MindWatch watch;
    private final StepLog.Writer log;
    private volatile List<String> lastCommands = List.of();
    private volatile List<SensorInfo> lastReadings = List.of();
    private final Map<String, Pose> boxesAtStart;

    /**
     * @param agent     the robot's agent, or null (none to watch)
     * @param inspector where its frames go, under the agent's name, or null
     * @param log       the robot's step log, or null
     */
    RobotTap(SimWorld world, Robot robot, Agent agent, Inspector inspector, StepLog.Writer log) {
        this.world = world;
        this.robot = robot;
        this.log = log;
        this.boxesAtStart = fixedBoxes(world);
        this.watch = agent == null ? null : MindWatch.attach(inspector, agent, this::robotView);
    }

    /**
     * Opens a step log at {@code file} whose past the inspector (if any) reads, beyond its memory,
     * as agent {@code agent}'s. {@return the writer}
     */
    static StepLog.Writer open(Path file, StepLog.Header header, Inspector inspector, String agent) throws IOException {
        var log = new StepLog.Writer(file, header);
        if (inspector != null) {
            archive(inspector, log, file, header, agent);
        }
        return log;
    }

    /** The inspector reads agent {@code agent}'s past, beyond its memory, from the step log being written. */
    static void archive(Inspector inspector, StepLog.Writer log, Path file, StepLog.Header header, String agent) {
        var archive = StepArchive.live(file, header);
        log.onChunk(archive::add);
        inspector.add(agent).archive(archive);
    }

    /** {@return the watch on the robot's agent, or null} */
    MindWatch watch() {
        return watch;
    }

    /** What the step log records of the world at a control step: the robot's body, the world's objects. */
    record Seen(StepLog.Body body, List<ObjectState> objects) {
    }

    /** {@return the world now, as the step log records it} On the simulation thread, or with the world waiting for the agent. */
    Seen see() {
        synchronized (world) {
            // not world.snapshot(): it copies the whole trajectory, every step
            var p = robot.pose();
            return new Seen(new StepLog.Body(p.x(), p.z(), p.heading(), robot.hasBattery() ? robot.getBattery().energy() : null,
                    robot.getWheels().getLeftSpeed(), robot.getWheels().getRightSpeed(),
                    robot.hasGripper() ? robot.getGripper().heldObject() : null, robot.contactTime()), world.supervisor().objects());
        }
    }

    /**
     * Records one control step, the world read now (it waits for the agent: a lockstep run's step).
     * {@return the agent's mind then, or null without an agent}
     */
    MindState afterStep(StepData data, List<Command> commands) {
        note(data, commands);
        return record(data, commands, log == null ? null : see());
    }

    /** Keeps a step's commands and readings for the inspector's view of the robot. */
    void note(StepData data, List<Command> commands) {
        var text = new ArrayList<String>(commands.size());
        commands.forEach(c -> text.add(c.toString()));
        if (!commands.isEmpty()) {
            lastCommands = text;
        }
        lastReadings = data.readings();
    }

    /**
     * Captures the agent's mind (on its thread, between cycles) and writes the step to the step log
     * with the world as {@code seen} at that step (null without a step log). {@return the mind, or null without an agent}
     */
    MindState record(StepData data, List<Command> commands, Seen seen) {
        MindState mind = watch == null ? null : watch.capture();
        if (log != null) {
            log.step(data.simTimeMs(), seen.body(), commands, data.readings(), mind, seen.objects());
        }
        return mind;
    }

    private RobotView robotView() {
        var readings = new ArrayList<String>();
        lastReadings.forEach(r -> readings.add(StepLog.reading(r)));
        return view(world, robot, lastCommands, readings, boxesAtStart);
    }

    /** {@return where the world's fixed boxes stand now, by id: the world file's events may move one later} */
    static Map<String, Pose> fixedBoxes(SimWorld world) {
        synchronized (world) {
            var at = new HashMap<String, Pose>();
            for (ObjectState o : world.supervisor().objects()) {
                if (!o.movable() && o.kind() == ObjectKind.BOX) {
                    at.put(o.id(), o.pose());
                }
            }
            return at;
        }
    }

    /** @param boxesAtStart the fixed boxes where they stood ({@link #fixedBoxes}): one placed elsewhere since is in the view */
    static RobotView view(SimWorld world, Robot robot, List<String> commands, List<String> readings, Map<String, Pose> boxesAtStart) {
        synchronized (world) {
            var p = robot.pose();
            var placed = new ArrayList<RobotView.Placed>();
            for (ObjectState o : world.supervisor().objects()) {
                if (o.movable() || boxesAtStart.containsKey(o.id()) && !o.pose().equals(boxesAtStart.get(o.id()))) {
                    placed.add(new RobotView.Placed(o.id(), StepLog.round(o.pose().x()), StepLog.round(o.pose().z()),
                            StepLog.round(o.pose().heading()), o.carriedBy()));
                }
            }
            return new RobotView(world.timeMs(), p.x(), p.z(), p.heading(),
                    robot.hasBattery() ? robot.getBattery().energy() : null, robot.getWheels().getLeftSpeed(),
                    robot.getWheels().getRightSpeed(), commands, placed, readings);
        }
    }

    void close() throws IOException {
        if (log != null) {
            log.close();
        }
    }
}
