package jacabot.robot.baseline;

import jacabot.sim.device.Camera;
import jacabot.sim.device.Compass;
import jacabot.sim.device.DistanceSensor;
import jacabot.sim.device.Gps;
import jacabot.sim.device.Gripper;
import jacabot.sim.device.Section;
import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import jacabot.sim.robot.Robot;

/**
 * The Khepera's devices and the helper functions the thesis' C programs keep beside their main
 * loop: {@code isRed} (image processing), {@code convertBearing}, the desired bearing towards a
 * point, the grip-force test. Readings only; the strategy lives in the baselines.
 */
final class KheperaIo {
    /** Red must exceed green and blue by this factor (the middleware's {@code red > 2*green}, §2.2). */
    static final double RED_RATIO = 2;

    final DistanceSensor left, frontLeft, front, frontRight, right;
    final Camera camera;
    final Gps gps;
    final Compass compass;
    final Gripper gripper;
    final Robot robot;

    /** Looks the devices up and enables them all at {@code period} ms. */
    KheperaIo(Robot robot, int period) {
        this.robot = robot;
        left = sensor(robot, "left", period);
        frontLeft = sensor(robot, "front-left", period);
        front = sensor(robot, "front", period);
        frontRight = sensor(robot, "front-right", period);
        right = sensor(robot, "right", period);
        camera = robot.getCamera("camera");
        camera.enable(period);
        gps = robot.getGps("gps");
        gps.enable(period);
        compass = robot.getCompass("compass");
        compass.enable(period);
        gripper = robot.getGripper();
        gripper.enableForceFeedback(period);
        gripper.enablePresence(period);
        robot.getBattery().enable(period);
    }

    private static DistanceSensor sensor(Robot robot, String name, int period) {
        DistanceSensor d = robot.getDistanceSensor(name);
        d.enable(period);
        return d;
    }

    /** {@return whether red rules a third of the camera image (C {@code isRed(image, part)})} */
    boolean isRed(Section section) {
        if (!camera.hasValue()) {
            return false;
        }
        Rgb c = camera.getSectionLevels(section);
        return c.red() > RED_RATIO * c.green() && c.red() > RED_RATIO * c.blue();
    }

    /** {@return whether the fingers squeeze something (the C test {@code -500 < force < -5})} */
    boolean gripping() {
        double force = gripper.getForceFeedback();
        return force > -500 && force < -5;
    }

    double x() {
        return gps.getValues()[0];
    }

    double z() {
        return gps.getValues()[2];
    }

    /** {@return the heading in degrees from the compass (C {@code convertBearing})} */
    double bearing() {
        double[] v = compass.getValues();
        double b = Math.toDegrees(Math.atan2(v[0], v[2]) - Math.PI / 2);
        return Pose.normalize(b);
    }

    double battery() {
        return robot.getBattery().getValue();
    }

    /** {@return the distance from the robot's centre (GPS) to a point} */
    double distanceTo(double tx, double tz) {
        return Math.hypot(tx - x(), tz - z());
    }

    /** {@return the compass bearing from the robot to a point (north = +x, east = +z; thesis Fig. 4.6)} */
    double bearingTo(double tx, double tz) {
        return Pose.normalize(Math.toDegrees(Math.atan2(tz - z(), tx - x())));
    }

    /** {@return desired minus current bearing brought into (-180, 180]: positive = turn right} */
    static double gap(double desired, double current) {
        double g = Pose.normalize(desired - current);
        return g > 180 ? g - 360 : g;
    }
}
