package jacabot.app.inspector;

import java.util.List;

/**
 * What the robot's side shows next to its agent's mind: the body's ground truth (pose, battery,
 * wheel speeds) and the middleware's last commands.
 *
 * @param battery energy in J, null without a battery
 */
public record RobotView(long timeMs, double x, double z, double heading, Double battery, double left, double right,
        List<String> commands) {
    public RobotView {
        commands = List.copyOf(commands);
    }
}
