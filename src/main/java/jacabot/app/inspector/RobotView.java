package jacabot.app.inspector;

import java.util.List;

/**
 * What the robot's side shows next to its agent's mind: the body's ground truth (pose, battery,
 * wheel speeds), the middleware's last commands, the readings the controller sent (the page draws
 * the distance sensors' rays from them) and where the world's movable objects are, and a fixed box
 * the world file's events moved (the page's drawing of the arena at that instant).
 *
 * @param battery energy in J, null without a battery
 * @param readings {@code KIND value} as in the step log ({@code FRONT_DISTANCE 512.0})
 */
public record RobotView(long timeMs, double x, double z, double heading, Double battery, double left, double right,
        List<String> commands, List<Placed> objects, List<String> readings) {
    public RobotView {
        commands = List.copyOf(commands);
        objects = objects == null ? List.of() : List.copyOf(objects);
        // the whole camera image is not shown (tens of KB a frame): its sections are
        readings = readings == null ? List.of() : readings.stream().filter(r -> !r.startsWith("CAMERA_IMAGE")).toList();
    }

    /** Without the objects and readings (a body alone). */
    public RobotView(long timeMs, double x, double z, double heading, Double battery, double left, double right,
            List<String> commands) {
        this(timeMs, x, z, heading, battery, left, right, commands, List.of(), List.of());
    }

    /** A movable object, or a fixed box an event moved, where it is, and who carries it (null: nobody). */
    public record Placed(String id, double x, double z, double heading, String carriedBy) {
    }
}
