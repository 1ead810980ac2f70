package jacabot.sim;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.geom.Pose;

import jacabot.sim.engine.Engine;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import java.util.List;

/**
 * The supervisor, after Webots' {@code Supervisor}: reads every pose and changes the world from
 * code (tests, the viewer's mouse, scenario scripts), the same things a world file's events do.
 * Every method takes effect at once, between physics steps, and is reported to the world's
 * listeners. Unknown names give {@link IllegalArgumentException}.
 */
public final class Supervisor {
    private final SimWorld world;
    private final Engine engine;

    Supervisor(SimWorld world, Engine engine) {
        this.world = world;
        this.engine = engine;
    }

    /** {@return the pose of an object or robot} */
    public Pose pose(String id) {
        synchronized (world) {
            return engine.pose(id);
        }
    }

    /** {@return every wall, box, cylinder and robot, in creation order} */
    public List<ObjectState> objects() {
        synchronized (world) {
            return engine.objects();
        }
    }

    /** Moves a box, cylinder or robot, keeping its heading (a carried cylinder is let go). */
    public void move(String id, double x, double z) {
        move(id, x, z, Double.NaN);
    }

    /** Moves a box, cylinder or robot and turns it to {@code heading} degrees (NaN: keep). */
    public void move(String id, double x, double z, double heading) {
        synchronized (world) {
            engine.move(id, x, z, heading);
        }
    }

    /** Adds a box. @throws IllegalArgumentException when the id is taken */
    public void addBox(BoxSpec box) {
        synchronized (world) {
            engine.addBox(box);
        }
    }

    /** Adds a cylinder. @throws IllegalArgumentException when the id is taken */
    public void addCylinder(CylinderSpec cylinder) {
        synchronized (world) {
            engine.addCylinder(cylinder);
        }
    }

    /** Removes a box or cylinder; {@return whether it existed} */
    public boolean remove(String id) {
        synchronized (world) {
            return engine.remove(id);
        }
    }

    /** Knocks the cylinder a robot carries out of its gripper; {@return whether it carried one} */
    public boolean knockCarried(String robot) {
        synchronized (world) {
            return engine.knock(robot);
        }
    }

    /** {@return the id of the cylinder a robot holds, or null} */
    public String carried(String robot) {
        synchronized (world) {
            return engine.carried(robot);
        }
    }

    /** Drains a robot's battery by {@code joules} (not below 0). */
    public void drainBattery(String robot, double joules) {
        synchronized (world) {
            engine.drain(robot, joules);
        }
    }

    /** Sets a robot's battery energy in joules (clamped to [0, max]). */
    public void setBattery(String robot, double joules) {
        synchronized (world) {
            engine.robot(robot).getBattery().setEnergy(joules);
        }
    }
}
