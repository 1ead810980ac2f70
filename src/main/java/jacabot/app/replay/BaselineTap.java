package jacabot.app.replay;

import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.robot.Robot;
import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * The step log of a baseline run (the procedural controller, no agent): the robot's body and the
 * objects that moved, after each control step, as an agent's run records them (without a mind),
 * so that the baseline's runs replay and plot as the agent's do.
 */
public final class BaselineTap implements Closeable, WorldListener {
    private final SimWorld world;
    private final Robot robot;
    private final StepLog.Writer log;

    private BaselineTap(SimWorld world, StepLog.Writer log) {
        this.world = world;
        this.robot = world.robots().get(0);
        this.log = log;
    }

    /** Opens {@code outDir}/{@value StepLog#FILE} and listens to {@code world}'s control steps; call before it runs. */
    public static BaselineTap attach(SimWorld world, Path outDir, Experiment experiment, String controller) throws IOException {
        var header = new StepLog.Header(StepLog.FORMAT, experiment.id(), world.name(), world.seed(), world.controlStep(),
                world.robots().get(0).name(), controller, world.snapshot(), null);
        var tap = new BaselineTap(world, new StepLog.Writer(outDir.resolve(StepLog.FILE), header));
        world.addListener(tap);
        return tap;
    }

    @Override
    public void controlStepEnded(long timeMs) {
        var p = robot.pose();
        var body = new StepLog.Body(p.x(), p.z(), p.heading(), robot.hasBattery() ? robot.getBattery().energy() : null,
                robot.getWheels().getLeftSpeed(), robot.getWheels().getRightSpeed(),
                robot.hasGripper() ? robot.getGripper().heldObject() : null, robot.contactTime());
        log.stepText(timeMs, body, List.of(), List.of(), null, world.supervisor().objects());
    }

    @Override
    public void close() throws IOException {
        log.close();
    }
}
