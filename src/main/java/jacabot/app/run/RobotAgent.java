package jacabot.app.run;

import java.util.Objects;

/**
 * One of the agents that program a robot: its name (as in a {@code .mas2j}'s {@code agents:} line,
 * what {@code .send} addresses) and its program. A robot has one agent in the thesis; several share
 * its middleware artifact in the Chapter 6 wish "the single robot programmed by more agents".
 */
public record RobotAgent(String name, AgentSource source) {
    /** The name of a robot's only agent (the step log, replay and the inspector know it by it). */
    public static final String ALONE = "robot";

    public RobotAgent {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(source, "source");
    }
}
