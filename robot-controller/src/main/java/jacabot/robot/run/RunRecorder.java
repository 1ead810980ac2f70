package jacabot.robot.run;

import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.geom.Pose;
import jacabot.sim.SimWorld;
import jacabot.sim.geom.Vec2;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.robot.Robot;
import jacabot.sim.viewer.PngRenderer;
import jacabot.sim.world.AreaSpec;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Records what one robot did during a run, from ground truth, whoever drives it (an agent through
 * the middleware, or a procedural baseline): a {@link WorldListener} sampling the robot at the end
 * of every control step. {@link #attach} it before the run, read {@link #summary} after.
 *
 * <p>The event log holds one line per event, {@code t=12.340 picked cylinder red1}, with the
 * simulated time of the control step (or of the world event) in seconds and three decimals. It
 * carries no wall-clock time and no hash-ordered data, so two runs of the same world and seed give
 * the same text byte for byte. Lines: {@code picked cylinder ID}, {@code delivered cylinder ID at (x, z)},
 * {@code set down cylinder ID outside the storage area at (x, z)}, {@code lost cylinder ID},
 * {@code entered storage area with cylinder ID}, {@code entered storage area without a cylinder},
 * {@code left storage area}, {@code reached charger (E J)}, {@code left charger (E J)},
 * {@code battery empty}, {@code contact for S s} (uninterrupted contacts of a second or more, when
 * they end), {@code world: ...} (scripted events and supervisor actions), {@code controller: ...}
 * ({@link #note} lines from whoever drives the robot).
 *
 * <p>Areas are entered when the robot's centre comes within their radius and left when it is
 * more than {@link #EXIT_MARGIN} beyond it, so that a robot turning on the rim is not counted twice.
 * Calls come from the stepping thread (listener calls run inside {@code SimWorld.step}); read the
 * results after the run, or inside {@code synchronized (world)}.
 */
public final class RunRecorder implements WorldListener {
    /** Default side of a coverage grid cell, metres. */
    public static final double CELL_SIZE = 0.10;
    /** How far beyond an area's radius the centre must go for the robot to have left it, metres. */
    public static final double EXIT_MARGIN = 0.01;
    /** Uninterrupted contacts at least this long get a log line, seconds. */
    public static final double LOGGED_CONTACT = 1.0;

    private final SimWorld world;
    private final Robot robot;
    private final AreaSpec storage, charger;
    private final long startMs;
    private final double contactAtStart;
    private final double cellSize, minX, minZ;
    private final int cellsX, cellsZ;
    private final boolean[] visited;
    /** The pose at the end of the last control step (the trajectory itself is sim-world's, bounded). */
    private Pose last;
    private final List<String> events = new ArrayList<>();
    private final List<Double> pickTimes = new ArrayList<>(), deliveryTimes = new ArrayList<>();

    private long nowMs;
    private int cellsVisited, lost, entriesWithCylinder, entriesEmpty, chargerVisits;
    private double distance, contact, contactRun, longestContact, batteryMin, batteryLast, recharged;
    private boolean batteryEmptied, inStorage, onCharger;
    private String held;

    private RunRecorder(SimWorld world, String robotName, double cellSize) {
        if (!(cellSize > 0)) {
            throw new IllegalArgumentException("cell size must be positive, got " + cellSize);
        }
        this.world = world;
        this.robot = world.robot(robotName);
        this.storage = world.spec().storage();
        this.charger = world.spec().charger();
        this.startMs = world.timeMs();
        this.nowMs = startMs;
        this.cellSize = cellSize;
        double w = world.spec().arena().width(), d = world.spec().arena().depth();
        this.minX = -w / 2;
        this.minZ = -d / 2;
        this.cellsX = Math.max(1, (int) Math.round(w / cellSize));
        this.cellsZ = Math.max(1, (int) Math.round(d / cellSize));
        this.visited = new boolean[cellsX * cellsZ];
        Pose p = robot.pose();
        last = p;
        visit(p);
        contactAtStart = robot.contactTime();
        contact = contactAtStart;
        held = robot.hasGripper() ? robot.getGripper().heldObject() : null;
        batteryLast = robot.hasBattery() ? robot.getBattery().energy() : Double.NaN;
        batteryMin = batteryLast;
        inStorage = storage != null && storage.contains(p.position());
        onCharger = charger != null && charger.contains(p.position());
    }

    /** {@return a recorder of one robot with 10 cm coverage cells, listening to the world from now on} */
    public static RunRecorder attach(SimWorld world, String robotName) {
        return attach(world, robotName, CELL_SIZE);
    }

    /** {@return a recorder with coverage cells of {@code cellSize} metres, listening from now on} */
    public static RunRecorder attach(SimWorld world, String robotName, double cellSize) {
        RunRecorder r;
        synchronized (world) {
            r = new RunRecorder(world, robotName, cellSize);
        }
        world.addListener(r);
        return r;
    }

    /** Stops listening (the figures so far stay readable). */
    public void detach() {
        world.removeListener(this);
    }

    @Override
    public void controlStepEnded(long timeMs) {
        nowMs = timeMs;
        Pose p = robot.pose();
        distance += p.position().distanceTo(last.position());
        last = p;
        visit(p);
        recordContact();
        recordGripper();
        recordAreas(p.position());
        recordBattery();
    }

    @Override
    public void eventFired(long timeMs, String description) {
        log(timeMs, "world: " + description);
    }

    @Override
    public void eventFailed(long timeMs, String description, String reason) {
        log(timeMs, "world: failed " + description + ": " + reason);
    }

    /** Adds a controller's line to the event log at the current simulated time (as the C programs' printf). */
    public void note(String text) {
        log(world.timeMs(), "controller: " + text);
    }

    private void visit(Pose p) {
        int ix = Math.min(cellsX - 1, Math.max(0, (int) Math.floor((p.x() - minX) / cellSize)));
        int iz = Math.min(cellsZ - 1, Math.max(0, (int) Math.floor((p.z() - minZ) / cellSize)));
        if (!visited[ix * cellsZ + iz]) {
            visited[ix * cellsZ + iz] = true;
            cellsVisited++;
        }
    }

    private void recordContact() {
        double now = robot.contactTime();
        double added = now - contact;
        contact = now;
        if (added > 0) {
            contactRun += added;
            longestContact = Math.max(longestContact, contactRun);
        } else {
            if (contactRun >= LOGGED_CONTACT) {
                log(nowMs, f("contact for %.3f s", contactRun));
            }
            contactRun = 0;
        }
    }

    private void recordGripper() {
        String now = robot.hasGripper() ? robot.getGripper().heldObject() : null;
        if (held != null && !held.equals(now)) {
            released(held);
        }
        if (now != null && !now.equals(held)) {
            pickTimes.add(seconds(nowMs));
            log(nowMs, "picked cylinder " + now);
        }
        held = now;
    }

    /** A cylinder left the gripper: set down (fingers opening) or lost (knocked, moved or removed). */
    private void released(String id) {
        ObjectState c = cylinder(id);
        if (c == null) {
            lost++;
            log(nowMs, "lost cylinder " + id + " (removed)");
        } else if (robot.getGripper().getGripPosition() >= 1) {
            lost++;
            log(nowMs, "lost cylinder " + id + f(" at (%.3f, %.3f)", c.pose().x(), c.pose().z()));
        } else if (storage != null && storage.contains(c.pose().position())) {
            deliveryTimes.add(seconds(nowMs));
            log(nowMs, "delivered cylinder " + id + f(" at (%.3f, %.3f)", c.pose().x(), c.pose().z()));
        } else {
            log(nowMs, "set down cylinder " + id + f(" outside the storage area at (%.3f, %.3f)", c.pose().x(), c.pose().z()));
        }
    }

    private ObjectState cylinder(String id) {
        for (ObjectState o : world.supervisor().objects()) {
            if (o.kind() == ObjectKind.CYLINDER && o.id().equals(id)) {
                return o;
            }
        }
        return null;
    }

    private void recordAreas(Vec2 at) {
        if (storage != null) {
            boolean was = inStorage;
            inStorage = inside(storage, at, was);
            if (inStorage && !was) {
                if (held != null) {
                    entriesWithCylinder++;
                    log(nowMs, "entered storage area with cylinder " + held);
                } else {
                    entriesEmpty++;
                    log(nowMs, "entered storage area without a cylinder");
                }
            } else if (was && !inStorage) {
                log(nowMs, "left storage area");
            }
        }
        if (charger != null) {
            boolean was = onCharger;
            onCharger = inside(charger, at, was);
            if (onCharger && !was) {
                chargerVisits++;
                log(nowMs, "reached charger" + energy());
            } else if (was && !onCharger) {
                log(nowMs, "left charger" + energy());
            }
        }
    }

    /** The battery's energy for an event's text, made only when there is an event (formatting costs at every step). */
    private String energy() {
        return robot.hasBattery() ? f(" (%.1f J)", robot.getBattery().energy()) : "";
    }

    /** Inside an area, with hysteresis: a robot already in stays in until EXIT_MARGIN beyond the rim. */
    private static boolean inside(AreaSpec area, Vec2 at, boolean wasInside) {
        double d = at.distanceTo(area.centre());
        return wasInside ? d <= area.radius() + EXIT_MARGIN : d <= area.radius();
    }

    private void recordBattery() {
        if (!robot.hasBattery()) {
            return;
        }
        double e = robot.getBattery().energy();
        if (e > batteryLast) {
            recharged += e - batteryLast;
        }
        batteryLast = e;
        batteryMin = Math.min(batteryMin, e);
        if (e <= 0 && !batteryEmptied) {
            batteryEmptied = true;
            log(nowMs, "battery empty");
        }
    }

    private void log(long timeMs, String text) {
        events.add(f("t=%.3f ", seconds(timeMs)) + text);
    }

    private static double seconds(long ms) {
        return ms / 1000.0;
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }

    /**
     * {@return the robot's poses, one per control step since the world started, as sim-world keeps
     * them (thinned past 32,768 poses: see {@code Robot.trajectory()}); the recorder keeps no copy, so
     * an hour's run does not grow the heap}
     */
    public List<Pose> trajectory() {
        return robot.trajectory();
    }

    /** {@return the event log so far, one line per event} */
    public List<String> events() {
        return List.copyOf(events);
    }

    /** {@return the figures so far} @param controller who drove the robot, e.g. "baseline" or "agent" */
    public RunSummary summary(String controller) {
        return new RunSummary(world.name(), robot.name(), controller, world.seed(), seconds(nowMs - startMs),
                distance, (double) cellsVisited / visited.length, cellSize, cellsVisited, visited.length,
                contact - contactAtStart, longestContact,
                pickTimes.size(), pickTimes, deliveryTimes.size(), deliveryTimes, lost,
                entriesWithCylinder, entriesEmpty,
                robot.hasBattery() ? batteryMin : null, batteryEmptied, chargerVisits, recharged, events);
    }

    /** Writes a PNG of the world now, with the robots' trajectories, through sim-world's renderer. */
    public void writePng(Path png, int width, int height) throws IOException {
        PngRenderer.write(world, png, width, height);
    }
}
