package jacabot.app.inspector;

import java.util.List;

/**
 * What the robot's side shows next to its agent's mind: the body's ground truth (pose, battery,
 * wheel speeds), the middleware's last commands, and where the world's movable objects are (the
 * page's drawing of the arena at that instant).
 *
 * @param battery energy in J, null without a battery
 */
public record RobotView(long timeMs, double x, double z, double heading, Double battery, double left, double right,
        List<String> commands, List<Placed> objects) {
    public RobotView {
        commands = List.copyOf(commands);
        objects = objects == null ? List.of() : List.copyOf(objects);
    }

    /** Without the objects (a body alone). */
    public RobotView(long timeMs, double x, double z, double heading, Double battery, double left, double right,
            List<String> commands) {
        this(timeMs, x, z, heading, battery, left, right, commands, List.of());
    }

    /** A movable object where it is, and who carries it (null: nobody). */
    public record Placed(String id, double x, double z, double heading, String carriedBy) {
    }
}
