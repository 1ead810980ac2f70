package jacabot.robot;

import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.sim.device.Camera;
import jacabot.sim.device.Compass;
import jacabot.sim.device.DistanceSensor;
import jacabot.sim.device.Gps;
import jacabot.sim.robot.Robot;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * The polling half of the controller (thesis Chapter 4, Introduction: "polling the sensors through
 * low-level APIs"): enables the robot's devices and, each control step, turns every enabled device
 * that has a reading into one {@link SensorInfo}. Only the simulation thread calls it.
 */
final class DeviceSampler {
    private final Robot robot;
    private boolean cameraImage; // whole images too: from the configuration, or asked for by enableSensor
    private final Map<SensorKind, DistanceSensor> distance = new EnumMap<>(SensorKind.class);
    private final Camera camera;
    /** The robot's GPS and compass, looked up once (null: the model has none). */
    private final Gps gps;
    private final Compass compass;

    DeviceSampler(Robot robot, boolean cameraImage) {
        this.robot = robot;
        this.cameraImage = cameraImage;
        for (DistanceSensor d : robot.distanceSensors()) {
            SensorKind.ofDistanceSensor(d.name()).ifPresent(k -> distance.put(k, d));
        }
        this.camera = robot.model().camera() == null ? null : robot.getCamera(robot.model().camera().name());
        this.gps = robot.model().gps() ? robot.getGps("gps") : null;
        this.compass = robot.model().compass() ? robot.getCompass("compass") : null;
    }

    /**
     * Enables every device the robot has, at one sampling period (Webots: first reading one period
     * later). {@return the ids of the kinds enabled: what the greeting declares}
     */
    List<Integer> enableAll(int periodMs) {
        var ids = new ArrayList<Integer>();
        for (SensorKind k : SensorKind.values()) {
            if (toggle(k, periodMs)) { // not enable(): whole images only when configured or asked for
                ids.add(k.id());
            }
        }
        return ids;
    }

    /** {@return whether the robot has a device for this kind (and it was enabled)} */
    boolean enable(SensorKind kind, int periodMs) {
        if (kind == SensorKind.CAMERA_IMAGE && camera != null) {
            if (camera.getSamplingPeriod() == 0) {
                camera.enable(periodMs); // a camera already running keeps its period
            }
            cameraImage = true;
            return true;
        }
        return toggle(kind, periodMs);
    }

    boolean disable(SensorKind kind) {
        if (kind == SensorKind.CAMERA_IMAGE) {
            cameraImage = false; // the image only: the camera keeps serving its sections
            return camera != null;
        }
        return toggle(kind, 0);
    }

    /** Enables (period > 0) or disables (0) the device behind a kind. */
    private boolean toggle(SensorKind kind, int periodMs) {
        boolean on = periodMs > 0;
        switch (kind) {
            case CAMERA_SECTIONS:
            case CAMERA_IMAGE:
                if (camera == null) {
                    return false;
                }
                if (on) {
                    camera.enable(periodMs);
                } else {
                    camera.disable();
                }
                return true;
            case GPS:
                if (!robot.model().gps()) {
                    return false;
                }
                if (on) {
                    robot.getGps("gps").enable(periodMs);
                } else {
                    robot.getGps("gps").disable();
                }
                return true;
            case COMPASS:
                if (!robot.model().compass()) {
                    return false;
                }
                if (on) {
                    robot.getCompass("compass").enable(periodMs);
                } else {
                    robot.getCompass("compass").disable();
                }
                return true;
            case BATTERY:
                if (!robot.hasBattery()) {
                    return false;
                }
                if (on) {
                    robot.getBattery().enable(periodMs);
                } else {
                    robot.getBattery().disable();
                }
                return true;
            case GRIP_FORCE:
                if (!robot.hasGripper()) {
                    return false;
                }
                if (on) {
                    robot.getGripper().enableForceFeedback(periodMs);
                } else {
                    robot.getGripper().disableForceFeedback();
                }
                return true;
            case GRIP_PRESENCE:
                if (!robot.hasGripper()) {
                    return false;
                }
                if (on) {
                    robot.getGripper().enablePresence(periodMs);
                } else {
                    robot.getGripper().disablePresence();
                }
                return true;
            case GRIPPER_POSITIONS:
                return robot.hasGripper(); // positions are actuator state, always readable
            case WHEEL_SPEEDS:
                return true;
            default:
                DistanceSensor d = distance.get(kind);
                if (d == null) {
                    return false;
                }
                if (on) {
                    d.enable(periodMs);
                } else {
                    d.disable();
                }
                return true;
        }
    }

    /** {@return the readings available now, in a fixed order (so a lockstep run is reproducible)} */
    List<SensorInfo> sample() {
        List<SensorInfo> out = new ArrayList<>(SensorKind.values().length); // at most one reading a kind: never grown
        for (Map.Entry<SensorKind, DistanceSensor> e : distance.entrySet()) {
            if (e.getValue().hasValue()) {
                out.add(new SensorInfo(e.getKey().id(), e.getValue().getValue()));
            }
        }
        if (camera != null && camera.hasValue()) {
            int[] levels = new int[9]; // left, centre, right thirds; red, green, blue each
            camera.copySectionLevelsInto(levels, 0);
            out.add(new SensorInfo(SensorKind.CAMERA_SECTIONS.id(), levels));
            if (cameraImage) {
                // width, height, then the pixels: one array made per image, the reading's own
                int[] framed = new int[camera.getWidth() * camera.getHeight() + 2];
                framed[0] = camera.getWidth();
                framed[1] = camera.getHeight();
                camera.copyImageInto(framed, 2);
                out.add(SensorInfo.owning(SensorKind.CAMERA_IMAGE.id(), framed));
            }
        }
        if (gps != null && gps.hasValue()) {
            double[] v = gps.getValues();
            out.add(new SensorInfo(SensorKind.GPS.id(), v[0], v[1], v[2]));
        }
        if (compass != null && compass.hasValue()) {
            double[] v = compass.getValues();
            out.add(new SensorInfo(SensorKind.COMPASS.id(), v[0], v[1], v[2]));
        }
        if (robot.hasBattery() && robot.getBattery().hasValue()) {
            out.add(new SensorInfo(SensorKind.BATTERY.id(), robot.getBattery().getValue()));
        }
        if (robot.hasGripper()) {
            var g = robot.getGripper();
            addIfReady(out, SensorKind.GRIP_FORCE, g.getForceFeedback());
            addIfReady(out, SensorKind.GRIP_PRESENCE, g.getPresence());
            out.add(new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[] {g.getArmPosition(), g.getGripPosition()}));
        }
        var w = robot.getWheels();
        out.add(new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {w.getLeftSpeed(), w.getRightSpeed()}));
        return out;
    }

    private static void addIfReady(List<SensorInfo> out, SensorKind kind, double value) {
        if (!Double.isNaN(value)) {
            out.add(new SensorInfo(kind.id(), value));
        }
    }
}
