package jacabot.app.run;

import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.NavigationMiddleware;
import jacabot.experiments.ObjectPickingMiddleware;
import jacabot.experiments.ObstacleAvoidanceMiddleware;
import jacabot.experiments.SuspendResumeMiddleware;
import jacabot.robot.Experiment;

/** The middleware artifact (executive layer) of each experiment. */
public final class Middlewares {
    private Middlewares() {
    }

    /** {@return the middleware artifact class that the experiment's agent focuses on} */
    public static Class<? extends MiddlewareArtifact> of(Experiment experiment) {
        switch (experiment) {
            case OBSTACLE_AVOIDANCE:
                return ObstacleAvoidanceMiddleware.class;
            case OBJECT_PICKING:
                return ObjectPickingMiddleware.class;
            case NAVIGATION:
                return NavigationMiddleware.class;
            case SUSPEND_RESUME:
            case TIDY_UP: // battery, charger and storage: all tidy-up needs
                return SuspendResumeMiddleware.class;
            default:
                throw new IllegalArgumentException("no middleware for " + experiment);
        }
    }
}
