package jacabot.sim.robot;

import jacabot.sim.geom.Rgb;
import jacabot.sim.device.LookupTable;
import java.util.List;
import java.util.Optional;

/**
 * A robot model: body, wheels and the devices it carries. Two models exist, after the thesis'
 * robots (Chapter 4): {@link #MYBOT} and {@link #KHEPERA}. Lengths in metres, angles in degrees
 * (relative bearings: positive = towards the robot's right), times in seconds, energy in joules.
 *
 * @param radius    the body is a disc of this radius
 * @param shellReflectance the share of infra-red light the body returns to another robot's distance
 *                  sensors (0..1); a painted object's is its colour's red channel / 255, but a shell
 *                  is rated on its own so that robots of any colour see each other (thesis Chapter 6:
 *                  several robots in one world), as real Kheperas' proximity sensors see each other
 * @param speedUnit metres per second of one wheel speed unit
 * @param camera    null when the model has none (likewise gripper and battery)
 */
public record RobotModel(String name, double radius, double height, Rgb color, double shellReflectance, double mass, double axleLength,
                         double speedUnit, double maxSpeed, List<DistanceSensorDef> distanceSensors,
                         CameraDef camera, GripperDef gripper, boolean gps, boolean compass, BatteryDef battery) {

    /** A distance sensor on the body's rim at relative bearing {@code rim}, pointing at relative bearing {@code direction}. */
    public record DistanceSensorDef(String name, double rim, double direction, double aperture, int rays, LookupTable table) {
    }

    /** A camera at the front rim, {@code mountHeight} above the floor, looking straight ahead. */
    public record CameraDef(String name, int width, int height, double fov, double mountHeight, double range) {
    }

    /**
     * The gripper: a cylinder can be grasped when its centre lies {@code reachMin}..{@code reachMax}
     * ahead of the robot's centre and at most {@code lateral} to the side; a held cylinder sits
     * {@code hold} ahead of the centre.
     */
    public record GripperDef(double armTime, double gripTime, double gripForce, double reachMin, double reachMax,
                             double lateral, double hold) {
    }

    /** A battery: maximum energy, idle power and the power of both motors at full speed (watts). */
    public record BatteryDef(double maxEnergy, double idlePower, double motorPower) {
    }

    /**
     * Khepera infra-red table, distance (m) → raw value, noise 1 %: 0 → 1000, 0.015 → 480 ("very
     * close"), 0.025 → 350 ("obstacle"), 0.04 → 200 ("safe" below), 0.06 → 0 (range).
     */
    public static final LookupTable KHEPERA_TABLE = LookupTable.of(
            new double[] {0.000, 1000, 0.01},
            new double[] {0.015, 480, 0.01},
            new double[] {0.025, 350, 0.01},
            new double[] {0.040, 200, 0.01},
            new double[] {0.060, 0, 0.0});

    /**
     * MyBot table, distance (m) → raw value, noise 1 %: 0 → 1000, 0.05 → 480, 0.08 → 350
     * ("obstacle"), 0.12 → 200 ("safe" below), 0.2 → 0 (range).
     */
    public static final LookupTable MYBOT_TABLE = LookupTable.of(
            new double[] {0.00, 1000, 0.01},
            new double[] {0.05, 480, 0.01},
            new double[] {0.08, 350, 0.01},
            new double[] {0.12, 200, 0.01},
            new double[] {0.20, 0, 0.0});

    /** How much infra-red light a robot's shell returns: almost a white wall's (1), whatever its colour. */
    static final double SHELL_REFLECTANCE = 0.9;

    /** Webots' MyBot: a disc of 4.5 cm radius with two front infra-red sensors, "left" and "right". */
    public static final RobotModel MYBOT = new RobotModel("mybot", 0.045, 0.08, new Rgb(60, 90, 200), SHELL_REFLECTANCE, 1.0, 0.09,
            0.001, 100,
            List.of(new DistanceSensorDef("left", -20, -20, 30, 3, MYBOT_TABLE),
                    new DistanceSensorDef("right", 20, 20, 30, 3, MYBOT_TABLE)),
            null, null, false, false, null);

    /**
     * The Khepera with gripper, camera, GPS, compass and battery: five infra-red sensors "left",
     * "front-left", "front", "front-right", "right" at -90, -45, 0, 45, 90 degrees; a 64×8 camera
     * "camera" with a 60° field of view; gripper "gripper"; "gps"; "compass"; "battery".
     */
    public static final RobotModel KHEPERA = new RobotModel("khepera", 0.0285, 0.03, new Rgb(40, 140, 60), SHELL_REFLECTANCE, 0.08, 0.053,
            0.0005, 100,
            List.of(new DistanceSensorDef("left", -90, -90, 20, 3, KHEPERA_TABLE),
                    new DistanceSensorDef("front-left", -45, -45, 20, 3, KHEPERA_TABLE),
                    new DistanceSensorDef("front", 0, 0, 20, 3, KHEPERA_TABLE),
                    new DistanceSensorDef("front-right", 45, 45, 20, 3, KHEPERA_TABLE),
                    new DistanceSensorDef("right", 90, 90, 20, 3, KHEPERA_TABLE)),
            new CameraDef("camera", 64, 8, 60, 0.025, 1.5),
            new GripperDef(1.0, 0.5, 40, 0.035, 0.068, 0.015, 0.05),
            true, true, new BatteryDef(1000, 0.5, 2.0));

    /** {@return the models' names} */
    public static List<String> names() {
        return List.of(MYBOT.name, KHEPERA.name);
    }

    /** {@return the model of that name} */
    public static Optional<RobotModel> byName(String name) {
        if (MYBOT.name.equals(name)) {
            return Optional.of(MYBOT);
        }
        if (KHEPERA.name.equals(name)) {
            return Optional.of(KHEPERA);
        }
        return Optional.empty();
    }
}
