package jacabot.experiments.link;

import jacabot.robot.link.Command;
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
final class Heartbeat {
    private final long periodMs;
    private final Consumer<String> log;
    private final Supplier<RobotConnection> controller;
    private final CommandStream commands;
    private final AgentProbes agent;
    private final StepAcknowledgement acks;
    private final Runnable beat;
    private final Thread thread = new Thread(this::run, "middleware-heartbeat");
    /** Whether heartbeats are held back because the agent does not reason (logged once each way). */
    private boolean withheld;
    private volatile boolean stopped;

    /** {@code beat} sends one heartbeat to the current controller. */
    Heartbeat(LinkConfig config, Supplier<RobotConnection> controller, CommandStream commands, AgentProbes agent,
            StepAcknowledgement acks, Runnable beat) {
        this.periodMs = config.heartbeatMs();
        this.log = config.log();
        this.controller = controller;
        this.commands = commands;
        this.agent = agent;
        this.acks = acks;
        this.beat = beat;
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    void stop() {
        stopped = true;
        thread.interrupt();
    }

    private void run() {
        long periodNanos = TimeUnit.MILLISECONDS.toNanos(periodMs);
        try {
            while (!stopped) {
                // a pending lockstep acknowledgement is retried every millisecond
                Thread.sleep(acks.waiting() ? 1 : Math.max(1, periodMs / 2));
                RobotConnection c = controller.get();
                if (c != null) {
                    acks.retry();
                }
                if (c != null && !c.hello().lockstep() && System.nanoTime() - commands.lastSentNanos() >= periodNanos) {
                    beatIfAlive();
                }
            }
        } catch (InterruptedException e) {
            // closing
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
