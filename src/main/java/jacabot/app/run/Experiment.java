package jacabot.app.run;

import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.NavigationMiddleware;
import jacabot.experiments.ObjectPickingMiddleware;
import jacabot.experiments.ObstacleAvoidanceMiddleware;
import jacabot.experiments.SuspendResumeMiddleware;
import java.util.Locale;
import java.util.Optional;

/** The four experiments of the thesis' Chapter 4: their world, agent and middleware. */
public enum Experiment {
    OBSTACLE_AVOIDANCE(1, "obstacle avoidance with the two-sensor MyBot", ObstacleAvoidanceMiddleware.class),
    OBJECT_PICKING(2, "red-cylinder picking with the Khepera", ObjectPickingMiddleware.class),
    NAVIGATION(3, "navigation to the storage point with GPS and compass", NavigationMiddleware.class),
    SUSPEND_RESUME(4, "task suspend and resume on a low battery (Appendix B)", SuspendResumeMiddleware.class);

    private final int number;
    private final String summary;
    private final Class<? extends MiddlewareArtifact> middleware;

    Experiment(int number, String summary, Class<? extends MiddlewareArtifact> middleware) {
        this.number = number;
        this.summary = summary;
        this.middleware = middleware;
    }

    public int number() {
        return number;
    }

    public String summary() {
        return summary;
    }

    public Class<? extends MiddlewareArtifact> middleware() {
        return middleware;
    }

    /** {@return the name used for files and the command line, e.g. {@code suspend-resume}} */
    public String id() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** {@return the world file, relative to the project directory} */
    public String worldFile() {
        return "worlds/" + id() + ".json";
    }

    /** {@return the agent's source, on the class path (it is packaged with the agents module)} */
    public String agentResource() {
        return "/asl/" + id() + ".asl";
    }

    /** {@return the same experiment for the procedural baselines of robot-controller} */
    public jacabot.robot.Experiment baseline() {
        return jacabot.robot.Experiment.byId(id());
    }

    /** {@return the experiment for a name or number, e.g. "navigation" or "3"} */
    public static Optional<Experiment> parse(String text) {
        for (Experiment e : values()) {
            if (e.id().equals(text) || String.valueOf(e.number).equals(text)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    @Override
    public String toString() {
        return id();
    }
}
