package jacabot.experiments.link;

import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.LinkSecret;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.net.InetAddress;

/**
 * The link's two ends in this JVM, for its tests: this module's middleware end and the real
 * controller (robot-controller, a test dependency only) over a loopback socket on a free port, with
 * a fresh secret. The application's own pairing, which runs experiments, is {@code jacabot.app.run.InProcessLink}.
 */
final class BothEnds implements AutoCloseable {
    private final MiddlewareLink middleware;
    private final RobotController controller;

    private BothEnds(MiddlewareLink middleware, RobotController controller) {
        this.middleware = middleware;
        this.controller = controller;
    }

    /** Opens the middleware end, points the controller at it and starts the controller (not its world). */
    static BothEnds start(SimWorld world, ControllerConfig controllerConfig, LinkConfig linkConfig) throws IOException {
        return start(world, controllerConfig, linkConfig, false);
    }

    /**
     * As {@link #start(SimWorld, ControllerConfig, LinkConfig)}; with {@code turns}, the lockstep
     * controller takes the middleware's turns on its simulation thread ({@link MiddlewareLink#turnOnCaller}).
     */
    static BothEnds start(SimWorld world, ControllerConfig controllerConfig, LinkConfig linkConfig, boolean turns)
            throws IOException {
        LinkSecret secret = LinkSecret.random();
        MiddlewareLink link = MiddlewareLink.open(linkConfig.withBindAddress(InetAddress.getLoopbackAddress())
                .withPort(0).withSecret(secret));
        try {
            RobotController controller = new RobotController(world,
                    controllerConfig.withAddress(InetAddress.getLoopbackAddress().getHostAddress(), link.port())
                            .withSecret(secret));
            if (turns) {
                controller.takeTurnsWith(link.turnOnCaller());
            }
            controller.start();
            return new BothEnds(link, controller);
        } catch (RuntimeException e) {
            link.close();
            throw e;
        }
    }

    MiddlewareLink middleware() {
        return middleware;
    }

    RobotController controller() {
        return controller;
    }

    /** Stops the controller (it says goodbye), then the middleware. */
    @Override
    public void close() {
        controller.close();
        middleware.close();
    }
}
