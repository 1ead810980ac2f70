package jacabot.sim.robot;

import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Vec2;
import jacabot.sim.device.Battery;
import jacabot.sim.device.Camera;
import jacabot.sim.device.Compass;
import jacabot.sim.device.Device;
import jacabot.sim.device.DifferentialWheels;
import jacabot.sim.device.DistanceSensor;
import jacabot.sim.device.Gps;
import jacabot.sim.device.Gripper;
import jacabot.sim.device.Sensor;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * A simulated robot, after Webots' {@code Robot}: devices looked up by name, wheel speeds, and
 * ground truth for tests (pose, trajectory, contact time). Created by the world; a controller gets
 * it with {@code SimWorld.robot(name)}. Every device starts disabled / stopped, as in Webots.
 */
public final class Robot {
    private static final Rgb BACKGROUND = new Rgb(40, 40, 60);

    private final String name;
    private final RobotModel model;
    private final RobotHost host;
    private final Map<String, Device> devices = new LinkedHashMap<>();
    private final List<Sensor> sensors = new ArrayList<>();
    private final DifferentialWheels wheels;
    private final Gripper gripper;
    private final Battery battery;

    /** @param initialEnergy the battery's energy at start in joules, NaN for full */
    public Robot(String name, RobotModel model, RobotHost host, double initialEnergy) {
        this.name = name;
        this.model = model;
        this.host = host;
        this.wheels = add(new DifferentialWheels("wheels", model.maxSpeed(), model.speedUnit(), model.axleLength()));
        for (RobotModel.DistanceSensorDef d : model.distanceSensors()) {
            Supplier<Pose> mount = () -> rimPose(d.rim(), d.direction());
            addSensor(new DistanceSensor(d.name(), host::nowMs, d.table(), d.rays(), d.aperture(), mount,
                    host.rayCaster(), host.noise(d.name())));
        }
        RobotModel.CameraDef c = model.camera();
        if (c != null) {
            addSensor(new Camera(c.name(), host::nowMs, c.width(), c.height(), c.fov(), c.mountHeight(), c.range(),
                    () -> rimPose(0, 0), host.rayCaster(), host.floorColor(), BACKGROUND));
        }
        if (model.gps()) {
            addSensor(new Gps("gps", host::nowMs, host::pose, 0.0, host.noise("gps")));
        }
        if (model.compass()) {
            addSensor(new Compass("compass", host::nowMs, host::pose));
        }
        RobotModel.BatteryDef b = model.battery();
        if (b != null) {
            double start = Double.isNaN(initialEnergy) ? b.maxEnergy() : initialEnergy;
            battery = addSensor(new Battery("battery", host::nowMs, b.maxEnergy(), start, b.idlePower(), b.motorPower()));
        } else {
            battery = null;
        }
        RobotModel.GripperDef g = model.gripper();
        gripper = g == null ? null
                : add(new Gripper("gripper", host::nowMs, g.armTime(), g.gripTime(), g.gripForce(), host.graspHost()));
    }

    private <D extends Device> D add(D device) {
        devices.put(device.name(), device);
        return device;
    }

    private <S extends Sensor> S addSensor(S sensor) {
        sensors.add(sensor);
        return add(sensor);
    }

    /** The pose of a point on the rim at relative bearing {@code rim}, facing relative bearing {@code direction}. */
    private Pose rimPose(double rim, double direction) {
        Pose p = host.pose();
        Vec2 at = p.position().plus(Vec2.ofBearing(p.heading() + rim).times(model.radius()));
        return new Pose(at.x(), at.z(), p.heading() + direction);
    }

    /** {@return the robot's unique name} */
    public String name() {
        return name;
    }

    /** {@return the robot's model} */
    public RobotModel model() {
        return model;
    }

    /** {@return the device of that name} @throws IllegalArgumentException when there is none */
    public Device getDevice(String deviceName) {
        Device d = devices.get(deviceName);
        if (d == null) {
            throw new IllegalArgumentException("robot '" + name + "' (" + model.name() + ") has no device '" + deviceName
                    + "'; its devices are " + devices.keySet());
        }
        return d;
    }

    /** {@return the devices' names, in model order} */
    public List<String> getDeviceNames() {
        return List.copyOf(devices.keySet());
    }

    /** {@return every device, in model order} */
    public List<Device> devices() {
        return List.copyOf(devices.values());
    }

    private <D extends Device> D typed(String deviceName, Class<D> type) {
        Device d = getDevice(deviceName);
        if (!type.isInstance(d)) {
            throw new IllegalArgumentException("device '" + deviceName + "' of robot '" + name + "' is not a " + type.getSimpleName());
        }
        return type.cast(d);
    }

    public DistanceSensor getDistanceSensor(String deviceName) {
        return typed(deviceName, DistanceSensor.class);
    }

    /** {@return the distance sensors, in model order} */
    public List<DistanceSensor> distanceSensors() {
        List<DistanceSensor> out = new ArrayList<>();
        for (Device d : devices.values()) {
            if (d instanceof DistanceSensor s) {
                out.add(s);
            }
        }
        return out;
    }

    public Camera getCamera(String deviceName) {
        return typed(deviceName, Camera.class);
    }

    public Gps getGps(String deviceName) {
        return typed(deviceName, Gps.class);
    }

    public Compass getCompass(String deviceName) {
        return typed(deviceName, Compass.class);
    }

    /** {@return the battery} @throws IllegalArgumentException when the model has none */
    public Battery getBattery() {
        if (battery == null) {
            throw new IllegalArgumentException("robot '" + name + "' (" + model.name() + ") has no battery");
        }
        return battery;
    }

    /** {@return whether the model has a battery} */
    public boolean hasBattery() {
        return battery != null;
    }

    /** {@return the gripper} @throws IllegalArgumentException when the model has none */
    public Gripper getGripper() {
        if (gripper == null) {
            throw new IllegalArgumentException("robot '" + name + "' (" + model.name() + ") has no gripper");
        }
        return gripper;
    }

    /** {@return whether the model has a gripper} */
    public boolean hasGripper() {
        return gripper != null;
    }

    /** {@return the wheels} */
    public DifferentialWheels getWheels() {
        return wheels;
    }

    /** Sets the wheel speeds in speed units (clamped to ±max speed). */
    public void setSpeeds(double left, double right) {
        wheels.setSpeeds(left, right);
    }

    /** {@return the true pose now (ground truth, not a sensor reading)} */
    public Pose pose() {
        return host.pose();
    }

    /**
     * {@return the poses at the end of every control step since the start (the first is the start
     * pose)}; past 32,768 poses (22 minutes at 40 ms) every second is dropped and the stride doubles,
     * so a long run's trajectory keeps its shape in bounded memory (the latest pose is always last)
     */
    public List<Pose> trajectory() {
        return Collections.unmodifiableList(new ArrayList<>(host.trajectory()));
    }

    /** {@return the simulated seconds this robot has spent touching walls, obstacles or robots} */
    public double contactTime() {
        return host.contactTime();
    }

    /** {@return the simulated seconds this robot has spent touching another robot (part of {@link #contactTime})} */
    public double robotContactTime() {
        return host.robotContactTime();
    }

    /** Called by the world after each physics step: moves the gripper, takes due readings. */
    public void afterPhysicsStep(double dt, long nowMs) {
        if (gripper != null) {
            gripper.step(dt);
            gripper.tick(nowMs);
        }
        for (Sensor s : sensors) {
            s.tick(nowMs);
        }
    }
}
