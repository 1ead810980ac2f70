package jacabot.sim;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.engine.WorldSnapshot;

import jacabot.sim.device.Camera;
import jacabot.sim.device.DistanceSensor;
import jacabot.sim.device.Gripper;
import jacabot.sim.engine.Engine;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.Robot;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A simulated world: the entry point of sim-world. Load a world file, find a robot by name, enable
 * its devices, set wheel speeds and gripper commands, then {@link #step()}: simulated time advances
 * only there, by fixed physics steps, so the same world file and seed give the same run to the bit.
 *
 * <pre>{@code
 * SimWorld world = SimWorld.load(Path.of("worlds/object-picking.json"));
 * Robot khepera = world.robot("khepera");
 * DistanceSensor front = khepera.getDistanceSensor("front");
 * front.enable(world.controlStep());
 * khepera.setSpeeds(50, 50);
 * while (world.time() < 10) {
 *     world.step();                 // one control step (40 ms by default)
 *     if (front.getValue() > 480) khepera.setSpeeds(0, 0);
 * }
 * }</pre>
 *
 * Threads: stepping, snapshots and supervisor calls synchronise on this object. Device calls do
 * not: make them from the thread that steps, or inside {@code synchronized (world)}.
 */
public final class SimWorld {
    private final Engine engine;
    private final Supervisor supervisor;

    private SimWorld(WorldSpec spec) {
        this.engine = new Engine(spec);
        this.supervisor = new Supervisor(this, engine);
    }

    /** {@return the world of a world file} @throws WorldFileException naming the JSON path at fault */
    public static SimWorld load(Path worldFile) throws WorldFileException {
        return new SimWorld(WorldFileReader.read(worldFile));
    }

    /** {@return the world of a world file's text} @throws WorldFileException naming the JSON path at fault */
    public static SimWorld parse(String json, String sourceName) throws WorldFileException {
        return new SimWorld(WorldFileReader.parse(json, sourceName));
    }

    /** {@return the world of a checked spec} */
    public static SimWorld of(WorldSpec spec) {
        return new SimWorld(spec);
    }

    /** {@return the world's spec, as loaded} */
    public WorldSpec spec() {
        return engine.spec();
    }

    public String name() {
        return engine.spec().name();
    }

    /** {@return the physics step in ms} */
    public int basicTimeStep() {
        return engine.spec().basicTimeStep();
    }

    /** {@return the control step in ms (the thesis' TIME_STEP)} */
    public int controlStep() {
        return engine.spec().controlStep();
    }

    public long seed() {
        return engine.spec().seed();
    }

    /**
     * {@return the simulated time in ms} Read without the world's lock: a thread that stamps a
     * console line with it may hold the console's lock, which a step's listener also takes while
     * the world's lock is held (a fail-safe's warning), and the two would wait for each other.
     */
    public long timeMs() {
        return engine.nowMs();
    }

    /** {@return the simulated time in seconds} Without the lock, as {@link #timeMs}. */
    public double time() {
        return engine.nowMs() / 1000.0;
    }

    /** Advances the world by one control step. */
    public synchronized void step() {
        step(controlStep());
    }

    /**
     * Advances the world by {@code durationMs}, as Webots' {@code robot.step(duration)}.
     *
     * @throws IllegalArgumentException unless the duration is a positive multiple of the basic time step
     */
    public synchronized void step(int durationMs) {
        if (durationMs <= 0 || durationMs % basicTimeStep() != 0) {
            throw new IllegalArgumentException("step duration must be a positive multiple of the basic time step ("
                    + basicTimeStep() + " ms), got " + durationMs);
        }
        for (int i = durationMs / basicTimeStep(); i > 0; i--) {
            engine.physicsStep();
        }
    }

    /** {@return the robot of that name} @throws IllegalArgumentException when there is none */
    public Robot robot(String name) {
        return engine.robot(name);
    }

    /**
     * {@return wall-clock nanoseconds spent so far in the physics engine and in the devices
     * (sensing, gripper, battery), for benchmarks}
     */
    public synchronized long[] stepCost() {
        return new long[] {engine.physicsNanos(), engine.devicesNanos()};
    }

    /** {@return every robot, in file order} */
    public List<Robot> robots() {
        return engine.robots();
    }

    /** {@return the supervisor of this world} */
    public Supervisor supervisor() {
        return supervisor;
    }

    /** {@return how many scripted events have not fired yet} */
    public synchronized int pendingEvents() {
        return engine.pendingEvents();
    }

    public void addListener(WorldListener listener) {
        engine.addListener(listener);
    }

    public void removeListener(WorldListener listener) {
        engine.removeListener(listener);
    }

    /** {@return an immutable picture of the world now} */
    public synchronized WorldSnapshot snapshot() {
        List<WorldSnapshot.RobotState> robots = new ArrayList<>();
        for (Robot r : engine.robots()) {
            robots.add(robotState(r));
        }
        WorldSpec s = engine.spec();
        return new WorldSnapshot(s.name(), engine.nowMs(), s.arena(), s.storage(), s.charger(), engine.objects(), robots);
    }

    private static WorldSnapshot.RobotState robotState(Robot r) {
        List<WorldSnapshot.SensorRay> rays = new ArrayList<>();
        for (DistanceSensor d : r.distanceSensors()) {
            rays.add(new WorldSnapshot.SensorRay(d.name(), d.pose(), d.getRange(), d.getValue(), d.getMaxValue()));
        }
        int[] image = null;
        int w = 0, h = 0;
        if (r.model().camera() != null) {
            Camera c = r.getCamera(r.model().camera().name());
            image = c.getImage();
            w = c.getWidth();
            h = c.getHeight();
        }
        double arm = Double.NaN, grip = Double.NaN;
        String held = null;
        if (r.hasGripper()) {
            Gripper g = r.getGripper();
            arm = g.getArmPosition();
            grip = g.getGripPosition();
            held = g.heldObject();
        }
        double battery = r.hasBattery() ? r.getBattery().energy() : Double.NaN;
        double max = r.hasBattery() ? r.getBattery().getMaxEnergy() : Double.NaN;
        return new WorldSnapshot.RobotState(r.name(), r.model().name(), r.pose(), r.model().radius(), r.model().color(),
                r.trajectory(), rays, image, w, h, arm, grip, held, battery, max, r.contactTime());
    }
}
