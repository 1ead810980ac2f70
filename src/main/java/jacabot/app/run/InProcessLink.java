package jacabot.app.run;
import jacabot.experiments.link.LinkConfig;
import jacabot.experiments.link.MiddlewareLink;
import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.MemoryLink;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.net.InetAddress;

/**
 * The controller and the middleware in one JVM, joined by the real protocol over a loopback socket
 * on a free port ({@link #start}): what tests and single-process runs use instead of two processes.
 * On request, in lockstep, the controller's simulation thread also takes the middleware's turn of
 * each step ({@link MiddlewareLink#turnOnCaller}): the frames still cross the socket, but no thread
 * wakes up (off by default: measured slower on a loaded machine, docs/performance.md §9);
 * or by the same frames in memory ({@link #inMemory}, lockstep only): what sweeps use, without the
 * socket's system calls and thread hand-offs. Stepping the world is left to the caller
 * ({@code controller().runner()}).
 */
public final class InProcessLink implements AutoCloseable {
    private final MiddlewareLink middleware;
    private final RobotController controller;

    private InProcessLink(MiddlewareLink middleware, RobotController controller) {
        this.middleware = middleware;
        this.controller = controller;
    }

    /**
     * Opens the middleware on 127.0.0.1 and a free port, points the controller at it and starts it.
     * The configs' addresses are overridden, and both ends get a fresh secret of this run's.
     */
    public static InProcessLink start(SimWorld world, ControllerConfig controllerConfig, LinkConfig linkConfig)
            throws IOException {
        return start(world, controllerConfig, linkConfig, 0);
    }

    /** As {@link #start(SimWorld, ControllerConfig, LinkConfig)}, listening on {@code port} (0: a free one). */
    public static InProcessLink start(SimWorld world, ControllerConfig controllerConfig, LinkConfig linkConfig, int port)
            throws IOException {
        return start(world, controllerConfig, linkConfig, port, false);
    }

    /**
     * As {@link #start(SimWorld, ControllerConfig, LinkConfig, int)}; with {@code turns}, a lockstep
     * controller takes the middleware's turns ({@link RobotController#takeTurnsWith}).
     */
    public static InProcessLink start(SimWorld world, ControllerConfig controllerConfig, LinkConfig linkConfig, int port,
            boolean turns) throws IOException {
        LinkSecret secret = LinkSecret.random();
        MiddlewareLink link = MiddlewareLink.open(linkConfig.withBindAddress(InetAddress.getLoopbackAddress())
                .withPort(port).withSecret(secret));
        try {
            RobotController controller = new RobotController(world,
                    controllerConfig.withAddress(InetAddress.getLoopbackAddress().getHostAddress(), link.port())
                            .withSecret(secret));
            if (turns && controllerConfig.lockstep()) {
                controller.takeTurnsWith(link.turnOnCaller());
            }
            controller.start();
            return new InProcessLink(link, controller);
        } catch (RuntimeException e) {
            link.close();
            throw e;
        }
    }

    /**
     * Joins the two through a {@link MemoryLink}: the same frames and codecs as over the socket, read
     * on the simulation thread as soon as they are written; no port, so no secret either. The
     * controller connects at once, before this returns.
     *
     * @throws IllegalArgumentException when {@code controllerConfig} is not lockstep
     */
    public static InProcessLink inMemory(SimWorld world, ControllerConfig controllerConfig, LinkConfig linkConfig) {
        MemoryLink memory = new MemoryLink(world); // the lock the simulation thread holds through a control step
        MiddlewareLink link = MiddlewareLink.inMemory(linkConfig, memory);
        try {
            RobotController controller = new RobotController(world, controllerConfig, memory);
            controller.start();
            return new InProcessLink(link, controller);
        } catch (RuntimeException e) {
            link.close();
            throw e;
        }
    }

    public MiddlewareLink middleware() {
        return middleware;
    }

    public RobotController controller() {
        return controller;
    }

    /** Stops the controller (it says goodbye), then the middleware. */
    @Override
    public void close() {
        controller.close();
        middleware.close();
    }
}
