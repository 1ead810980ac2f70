package jacabot.sim.engine;

import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Vec2;
import jacabot.sim.robot.Robot;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.EventSpec;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The world's core: physics, robots, scripted events and simulated time, advanced one basic time
 * step at a time. Not thread-safe: {@code SimWorld} serialises access. Internal to sim-world; use
 * {@code SimWorld} and {@code Supervisor}.
 */
public final class Engine {
    private final WorldSpec spec;
    private final Physics physics;
    private final Map<String, RobotRuntime> robots = new LinkedHashMap<>();
    private final EventScheduler events;
    private final List<WorldListener> listeners = new CopyOnWriteArrayList<>();
    /** Volatile: other threads read the clock without the world's lock (console time stamps, heartbeats). */
    private volatile long nowMs;

    /** Builds the world of a checked spec. */
    public Engine(WorldSpec spec) {
        this.spec = spec;
        this.physics = new Physics(spec.basicTimeStep());
        physics.addArenaWalls(spec.arena());
        for (BoxSpec w : spec.walls()) {
            physics.addBox(w, ObjectKind.WALL);
        }
        for (BoxSpec b : spec.boxes()) {
            physics.addBox(b, ObjectKind.BOX);
        }
        for (CylinderSpec c : spec.cylinders()) {
            physics.addCylinder(c);
        }
        for (RobotSpec r : spec.robots()) {
            RobotModel model = RobotModel.byName(r.model())
                    .orElseThrow(() -> new IllegalArgumentException("unknown robot model '" + r.model() + "'"));
            robots.put(r.name(), new RobotRuntime(this, physics, r, model));
        }
        this.events = new EventScheduler(spec.events());
    }

    public WorldSpec spec() {
        return spec;
    }

    /** {@return the simulated time in ms} */
    public long nowMs() {
        return nowMs;
    }

    public void addListener(WorldListener l) {
        listeners.add(l);
    }

    public void removeListener(WorldListener l) {
        listeners.remove(l);
    }

    /** Advances the world by one basic time step. */
    public void physicsStep() {
        long t0 = System.nanoTime();
        for (RobotRuntime r : robots.values()) {
            r.applyWheels();
        }
        physics.step();
        long t1 = System.nanoTime();
        nowMs += spec.basicTimeStep();
        double dt = spec.basicTimeStep() / 1000.0;
        boolean controlEnd = nowMs % spec.controlStep() == 0;
        for (RobotRuntime r : robots.values()) {
            r.afterStep(dt, nowMs, spec.charger(), controlEnd);
        }
        physicsNanos += t1 - t0;
        devicesNanos += System.nanoTime() - t1;
        events.update(nowMs, this);
        if (controlEnd) {
            for (WorldListener l : listeners) {
                l.controlStepEnded(nowMs);
            }
        }
    }

    /** {@return the robot of that name} @throws IllegalArgumentException when there is none */
    public Robot robot(String name) {
        return runtime(name).robot();
    }

    /** Wall time spent in the physics engine and in the devices (sensors, gripper, battery), ns. */
    private long physicsNanos;
    private long devicesNanos;

    public long physicsNanos() {
        return physicsNanos;
    }

    public long devicesNanos() {
        return devicesNanos;
    }

    private RobotRuntime runtime(String name) {
        RobotRuntime r = robots.get(name);
        if (r == null) {
            throw new IllegalArgumentException("no robot named '" + name + "'; robots: " + robots.keySet());
        }
        return r;
    }

    public List<Robot> robots() {
        List<Robot> out = new ArrayList<>();
        for (RobotRuntime r : robots.values()) {
            out.add(r.robot());
        }
        return out;
    }

    /** {@return a noise generator for one device, or null when the world has sensor noise off} */
    Random noise(String robot, String device) {
        if (!spec.sensorNoise()) {
            return null;
        }
        long h = (robot + "/" + device).hashCode();
        return new Random(spec.seed() * 0x9E3779B97F4A7C15L ^ h * 0xC2B2AE3D27D4EB4FL);
    }

    void fired(String description) {
        for (WorldListener l : listeners) {
            l.eventFired(nowMs, description);
        }
    }

    // ---- supervisor operations

    /** {@return the pose of an object or robot} @throws IllegalArgumentException when unknown */
    public Pose pose(String id) {
        return object(id).pose();
    }

    private SimObject object(String id) {
        SimObject o = physics.get(id);
        if (o == null) {
            throw new IllegalArgumentException("no object named '" + id + "'");
        }
        return o;
    }

    /** {@return every object and robot, walls included, in creation order} */
    public List<ObjectState> objects() {
        List<ObjectState> out = new ArrayList<>();
        for (SimObject o : physics.objects()) {
            out.add(new ObjectState(o.id, o.kind, o.pose(), o.sizeX, o.sizeZ, o.height, o.color, o.movable, o.carriedBy));
        }
        return out;
    }

    /** Moves an object or robot (NaN heading: keep it); a carried cylinder is first let go. */
    public void move(String id, double x, double z, double heading) {
        SimObject o = object(id);
        if (o.kind == ObjectKind.WALL) {
            throw new IllegalArgumentException("walls cannot be moved: '" + id + "'");
        }
        if (o.carriedBy != null) {
            runtime(o.carriedBy).robot().getGripper().forget(id);
            o.carriedBy = null;
            o.setGhost(false);
        }
        o.place(x, z, Double.isNaN(heading) ? o.pose().heading() : heading);
        fired("moved '" + id + "' to (" + x + ", " + z + ")");
    }

    public void addBox(BoxSpec b) {
        physics.addBox(b, ObjectKind.BOX);
        fired("added box '" + b.id() + "'");
    }

    public void addCylinder(CylinderSpec c) {
        physics.addCylinder(c);
        fired("added cylinder '" + c.id() + "'");
    }

    /** Removes a box or cylinder; {@return whether it existed} */
    public boolean remove(String id) {
        SimObject o = physics.get(id);
        if (o == null) {
            return false;
        }
        if (o.kind == ObjectKind.WALL || o.kind == ObjectKind.ROBOT) {
            throw new IllegalArgumentException("only boxes and cylinders can be removed: '" + id + "'");
        }
        if (o.carriedBy != null) {
            runtime(o.carriedBy).robot().getGripper().forget(id);
        }
        physics.remove(id);
        fired("removed '" + id + "'");
        return true;
    }

    /** Knocks the carried cylinder out of a robot's gripper; {@return whether it carried one} */
    public boolean knock(String robot) {
        Robot r = robot(robot);
        return r.hasGripper() && r.getGripper().knock();
    }

    /** Drains a robot's battery by {@code joules}. */
    public void drain(String robot, double joules) {
        robot(robot).getBattery().drain(joules);
        fired("drained " + joules + " J from '" + robot + "'");
    }

    /** {@return the id of the cylinder a robot holds, or null} */
    public String carried(String robot) {
        Robot r = robot(robot);
        return r.hasGripper() ? r.getGripper().heldObject() : null;
    }

    /** Keeps a disc of radius {@code r} inside the arena. */
    Vec2 clampToArena(Vec2 p, double r) {
        double hx = spec.arena().halfWidth() - r, hz = spec.arena().halfDepth() - r;
        return new Vec2(Math.max(-hx, Math.min(hx, p.x())), Math.max(-hz, Math.min(hz, p.z())));
    }

    // ---- scripted events

    boolean isNear(EventSpec.Near near) {
        SimObject r = physics.get(near.robot()), o = physics.get(near.object());
        return r != null && o != null && r.pose().position().distanceTo(o.pose().position()) <= near.within();
    }

    void perform(EventSpec.Action action) {
        try {
            if (action instanceof EventSpec.Move m) {
                move(m.object(), m.x(), m.z(), m.heading());
            } else if (action instanceof EventSpec.AddBox a) {
                addBox(a.box());
            } else if (action instanceof EventSpec.AddCylinder a) {
                addCylinder(a.cylinder());
            } else if (action instanceof EventSpec.Remove rm) {
                if (!remove(rm.object())) {
                    throw new IllegalArgumentException("no object named '" + rm.object() + "'");
                }
            } else if (action instanceof EventSpec.Knock k) {
                if (!knock(k.robot())) {
                    throw new IllegalArgumentException("robot '" + k.robot() + "' carries nothing");
                }
            } else if (action instanceof EventSpec.Drain d) {
                drain(d.robot(), d.amount());
            }
        } catch (IllegalArgumentException e) {
            for (WorldListener l : listeners) {
                l.eventFailed(nowMs, action.toString(), e.getMessage());
            }
        }
    }

    /** {@return how many scripted events have not fired yet} */
    public int pendingEvents() {
        return events.remaining();
    }
}
