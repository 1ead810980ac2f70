package jacabot.sim.engine;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Pose;

import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.AreaSpec;
import java.util.List;

/**
 * An immutable picture of a world at one instant, for viewers and reports.
 *
 * @param storage null when the world has none (likewise charger)
 */
public record WorldSnapshot(String name, long timeMs, ArenaSpec arena, AreaSpec storage, AreaSpec charger,
                            List<ObjectState> objects, List<RobotState> robots) {

    /** A distance sensor's ray: where it starts and points, its range, its last value (NaN when disabled). */
    public record SensorRay(String name, Pose origin, double range, double value, double maxValue) {
    }

    /**
     * A robot: ground-truth pose, trajectory, sensor rays, last camera image (null when none),
     * gripper positions (NaN without a gripper), battery energy (NaN without a battery) and
     * contact time in seconds.
     */
    public record RobotState(String name, String model, Pose pose, double radius, Rgb color, List<Pose> trajectory,
                             List<SensorRay> rays, int[] cameraImage, int cameraWidth, int cameraHeight,
                             double armPosition, double gripPosition, String held, double battery, double batteryMax,
                             double contactTime) {
    }

    /** {@return the robot of that name, or null} */
    public RobotState robot(String robotName) {
        for (RobotState r : robots) {
            if (r.name().equals(robotName)) {
                return r;
            }
        }
        return null;
    }
}
