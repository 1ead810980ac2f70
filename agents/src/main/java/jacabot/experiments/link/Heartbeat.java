package jacabot.experiments.link;

import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Heartbeats to a real-time controller whenever no command went out for {@link LinkConfig#heartbeatMs()},
 * sent only while the agent reasons ({@link AgentProbes#alive()}): it is the agent's progress, not
 * this thread's, that keeps the controller's fail-safe quiet, so a stuck or dead agent stops the
 * robot as a dead process would. The same thread retries a lockstep {@link StepAcknowledgement}.
 * Lockstep controllers do not watch for silence (the world waits for us anyway): no heartbeats there.
 */
final class Heartbeat extends LinkThread {
    private final long periodMs;
    private final long periodNanos;
    private final Consumer<String> log;
    private final Supplier<RobotConnection> controller;
    private final CommandStream commands;
    private final AgentProbes agent;
    private final StepAcknowledgement acks;
    private final Runnable beat;
    /** Whether heartbeats are held back because the agent does not reason (logged once each way). */
    private boolean withheld;

    /** {@code beat} sends one heartbeat to the current controller. */
    Heartbeat(LinkConfig config, Supplier<RobotConnection> controller, CommandStream commands, AgentProbes agent,
            StepAcknowledgement acks, Runnable beat) {
        super("middleware-heartbeat");
        this.periodMs = config.heartbeatMs();
        this.periodNanos = TimeUnit.MILLISECONDS.toNanos(periodMs);
        this.log = config.log();
        this.controller = controller;
        this.commands = commands;
        this.agent = agent;
        this.acks = acks;
        this.beat = beat;
    }

    /** A waiting lockstep acknowledgement is retried every millisecond. */
    @Override
    long pauseMs() {
        return acks.waiting() ? 1 : Math.max(1, periodMs / 2);
    }

    @Override
    void round() {
        RobotConnection c = controller.get();
        if (c != null) {
            acks.retry();
        }
        if (c != null && !c.hello().lockstep() && System.nanoTime() - commands.lastSentNanos() >= periodNanos) {
            beatIfAlive();
        }
    }

    private void beatIfAlive() {
        if (agent.alive()) {
            if (withheld) {
                withheld = false;
                log.accept("the agent reasons again: heartbeats resume");
            }
            beat.run();
        } else if (!withheld) {
            withheld = true;
            log.accept("the agent does not reason: heartbeats withheld, "
                    + "the controller's fail-safe will stop the robot");
        }
    }
}
