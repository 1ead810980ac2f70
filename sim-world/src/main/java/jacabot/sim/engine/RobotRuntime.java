package jacabot.sim.engine;

import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Vec2;
import jacabot.sim.device.Battery;
import jacabot.sim.device.DifferentialWheels;
import jacabot.sim.device.GraspHost;
import jacabot.sim.device.RayCaster;
import jacabot.sim.robot.Robot;
import jacabot.sim.robot.RobotHost;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.RobotSpec;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/** Binds a {@link Robot} to its body: wheels, battery, gripper, trajectory and contact time. Internal. */
final class RobotRuntime implements RobotHost, GraspHost {
    private final Engine engine;
    private final Physics physics;
    private final SimObject body;
    private final RayCaster rayCaster;
    /** Poses kept at most (about 1.5 MB): past it the trajectory is thinned, so an hour's run keeps a flat heap. */
    static final int TRAJECTORY_LIMIT = 1 << 15;
    /** The pose every {@code stride} control steps, then the latest pose when it falls between two. */
    private final List<Pose> trajectory = new ArrayList<>();
    private int stride = 1;
    private long controlSteps;
    private boolean latestBetween;
    private final Robot robot;
    private double contactTime;
    private double robotContactTime;

    RobotRuntime(Engine engine, Physics physics, RobotSpec spec, RobotModel model) {
        this.engine = engine;
        this.physics = physics;
        this.body = physics.addRobot(spec.name(), model.radius(), model.height(), model.color(), model.shellReflectance(), spec.x(), spec.z(), spec.heading());
        this.rayCaster = physics.rayCaster(body);
        this.robot = new Robot(spec.name(), model, this, spec.battery());
        trajectory.add(pose());
    }

    Robot robot() {
        return robot;
    }

    SimObject body() {
        return body;
    }

    /** Before a physics step: the body's velocity from the wheel speeds (zero on an empty battery). */
    void applyWheels() {
        DifferentialWheels w = robot.getWheels();
        if (robot.hasBattery() && robot.getBattery().isEmpty()) {
            w.setSpeeds(0, 0);
        }
        double v = w.linearVelocity();
        double theta = body.body.getTransform().getRotationAngle();
        body.body.setLinearVelocity(v * Math.cos(theta), v * Math.sin(theta));
        body.body.setAngularVelocity(Math.toRadians(w.turnRate()));
    }

    /** After a physics step of {@code dt} seconds. */
    void afterStep(double dt, long nowMs, AreaSpec charger, boolean controlStepEnd) {
        if (physics.inContact(body)) {
            contactTime += dt;
            if (physics.touchesRobot(body)) {
                robotContactTime += dt;
            }
        }
        if (robot.hasBattery()) {
            Battery b = robot.getBattery();
            DifferentialWheels w = robot.getWheels();
            b.drain(b.power(w.getLeftSpeed() / w.getMaxSpeed(), w.getRightSpeed() / w.getMaxSpeed()) * dt);
            if (charger != null && charger.contains(pose().position())) {
                b.charge(charger.power() * dt);
            }
        }
        carryHeld();
        robot.afterPhysicsStep(dt, nowMs);
        if (controlStepEnd) {
            record(pose());
        }
    }

    /**
     * One pose per control step until {@link #TRAJECTORY_LIMIT}; then every second one is dropped and
     * the stride doubles (the picture of an hour keeps its shape), the latest pose always kept last.
     */
    private void record(Pose p) {
        controlSteps++;
        if (latestBetween) {
            trajectory.remove(trajectory.size() - 1);
        }
        trajectory.add(p);
        latestBetween = controlSteps % stride != 0;
        if (!latestBetween && trajectory.size() > TRAJECTORY_LIMIT) {
            int kept = 0;
            for (int i = 0; i < trajectory.size(); i += 2) {
                trajectory.set(kept++, trajectory.get(i));
            }
            boolean latestDropped = (trajectory.size() - 1) % 2 != 0;
            trajectory.subList(kept, trajectory.size()).clear();
            stride *= 2;
            if (latestDropped) {
                trajectory.add(p);
                latestBetween = true;
            }
        }
    }

    /** Moves a held cylinder to its place between the fingers. */
    void carryHeld() {
        if (!robot.hasGripper() || robot.getGripper().heldObject() == null) {
            return;
        }
        SimObject c = physics.get(robot.getGripper().heldObject());
        if (c != null) {
            Vec2 at = holdPoint();
            c.place(at.x(), at.z(), 0);
        }
    }

    private Vec2 holdPoint() {
        Pose p = pose();
        return p.position().plus(p.forward().times(robot.model().gripper().hold()));
    }

    // ---- RobotHost

    @Override
    public long nowMs() {
        return engine.nowMs();
    }

    @Override
    public Pose pose() {
        return body.pose();
    }

    @Override
    public RayCaster rayCaster() {
        return rayCaster;
    }

    @Override
    public GraspHost graspHost() {
        return this;
    }

    @Override
    public Random noise(String deviceName) {
        return engine.noise(body.id, deviceName);
    }

    @Override
    public Rgb floorColor() {
        return engine.spec().arena().floorColor();
    }

    @Override
    public List<Pose> trajectory() {
        return trajectory;
    }

    @Override
    public double contactTime() {
        return contactTime;
    }

    @Override
    public double robotContactTime() {
        return robotContactTime;
    }

    // ---- GraspHost

    @Override
    public String graspable() {
        RobotModel.GripperDef g = robot.model().gripper();
        Pose p = pose();
        Vec2 fwd = p.forward(), right = Vec2.ofBearing(p.heading() + 90);
        String best = null;
        double bestLateral = Double.POSITIVE_INFINITY;
        for (SimObject o : physics.objects()) {
            if (o.kind != ObjectKind.CYLINDER || o.carriedBy != null) {
                continue;
            }
            Vec2 d = o.pose().position().minus(p.position());
            double f = d.dot(fwd), l = Math.abs(d.dot(right));
            if (f >= g.reachMin() && f <= g.reachMax() && l <= g.lateral() && l < bestLateral) {
                best = o.id;
                bestLateral = l;
            }
        }
        return best;
    }

    @Override
    public void attach(String cylinderId) {
        SimObject c = physics.get(cylinderId);
        c.carriedBy = body.id;
        c.setGhost(true);
        carryHeld();
        engine.fired("robot '" + body.id + "' grasped '" + cylinderId + "'");
    }

    @Override
    public void release(String cylinderId, boolean knocked) {
        SimObject c = physics.get(cylinderId);
        if (c == null) {
            return;
        }
        Vec2 at;
        if (knocked) {
            Pose p = pose();
            double off = robot.model().radius() + c.radius() + 0.02;
            at = engine.clampToArena(p.position().plus(Vec2.ofBearing(p.heading() + 90).times(off)), c.radius());
        } else {
            at = holdPoint();
        }
        c.place(at.x(), at.z(), 0);
        c.carriedBy = null;
        c.setGhost(false);
        engine.fired("robot '" + body.id + "' " + (knocked ? "lost" : "set down") + " '" + cylinderId + "'");
    }
}
