package jacabot.experiments.link;

import jacabot.robot.link.Protocol;
import java.util.function.Consumer;

/**
 * The simulated time the agent sees, which never goes back: a controller that restarted counts from
 * 0 again, so its clock is moved on to continue from the last time seen (one control step later) and
 * {@code .wait} and timeouts in the agent keep working. Recovery, not in the thesis.
 */
final class ClockRebase {
    private final Consumer<String> log;
    /** The latest simulated time handed out, −1 before any. */
    private long lastSimTimeMs = -1;
    /** What is added to the current controller's clock. */
    private long offsetMs;
    /** Whether the current connection's first time was compared with the last one seen. */
    private boolean checked;

    ClockRebase(Consumer<String> log) {
        this.log = log;
    }

    /** A controller connected: its first time is checked against the last one seen. */
    synchronized void connected() {
        checked = false;
    }

    /** {@return the simulated time the agent sees for the controller's {@code raw} time} */
    synchronized long rebase(Protocol.Hello controller, long raw) {
        if (!checked) {
            checked = true;
            if (lastSimTimeMs >= 0 && raw + offsetMs < lastSimTimeMs) {
                offsetMs = lastSimTimeMs + controller.controlStepMs() - raw;
                log.accept("the controller's simulated clock went back to " + raw + " ms (a restart): "
                        + "times are moved on by " + offsetMs + " ms");
            }
        }
        long t = raw + offsetMs;
        lastSimTimeMs = Math.max(lastSimTimeMs, t);
        return t;
    }
}
