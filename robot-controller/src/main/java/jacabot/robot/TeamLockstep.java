package jacabot.robot;

import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.LongConsumer;

/**
 * The controllers' half of a team in lockstep (thesis Chapter 6, multi-robot systems): one world,
 * one {@link RobotController} per robot, and each control step
 * <ol>
 *   <li>every robot's devices are sampled, under the world's lock;</li>
 *   <li>every robot's step is sent ({@link RobotController#sendStep}), in the given order;</li>
 *   <li>the agents' turn: in this process, the agents reason on every robot's step; with the
 *       agents in another process, nothing here (their side answers once it has every robot's step);</li>
 *   <li>every robot's answer is awaited and applied ({@link RobotController#finishStep}), in the same order;</li>
 *   <li>the world advances one step.</li>
 * </ol>
 * A robot whose link has dropped (its agent died, its process ended) is stopped by its fail-safe and
 * no longer waited for: the others go on. {@code jacabot controller --lockstep} with a team world runs this.
 */
public final class TeamLockstep {
    /** The agents' turn of a step, after every robot's step is sent and before any answer is applied. */
    @FunctionalInterface
    public interface AgentsTurn {
        void run(long simTimeMs) throws InterruptedException;
    }

    private final SimWorld world;
    private final List<RobotController> robots;
    private final AgentsTurn agents;
    private final SimRunner runner;
    private LongConsumer afterStep = t -> {
    };
    private volatile boolean interrupted;

    /**
     * @param robots     the team's lockstep controllers of {@code world}, in the order the agents answer them
     * @param agentsTurn the agents' turn in this process, or null when they are in another
     */
    public TeamLockstep(SimWorld world, List<RobotController> robots, AgentsTurn agentsTurn) {
        for (RobotController r : robots) {
            if (r.world() != world || !r.config().lockstep()) {
                throw new IllegalArgumentException("robot " + r.robot().name() + ": a team's controllers are lockstep ones of its world");
            }
        }
        this.world = world;
        this.robots = List.copyOf(robots);
        this.agents = agentsTurn != null ? agentsTurn : t -> {
        };
        this.runner = new SimRunner(world, w -> this.robots.forEach(r -> r.controlStep(w)), this::exchange);
        runner.setMode(SimRunner.Mode.FAST); // the agents' answers pace the world
    }

    /** Called after each step's answers are applied, before the world advances, with the step's simulated time. */
    public TeamLockstep afterStep(LongConsumer listener) {
        this.afterStep = listener;
        return this;
    }

    /** {@return the runner: each of its steps is a team step} */
    public SimRunner runner() {
        return runner;
    }

    public List<RobotController> robots() {
        return robots;
    }

    /**
     * Waits until every robot's link has come up (the agents' process listens for each), up to
     * {@code timeoutMs}. {@return the robots still without a link, empty when all are up}
     */
    public List<String> awaitConnected(long timeoutMs) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        while (true) {
            List<String> missing = robots.stream().filter(r -> r.connections() == 0).map(r -> r.robot().name()).toList();
            if (missing.isEmpty() || System.nanoTime() >= end) {
                return missing;
            }
            Thread.sleep(10);
        }
    }

    /** {@return whether some robot's link is up} (none after the agents' process ended) */
    public boolean anyConnected() {
        return robots.stream().anyMatch(RobotController::isConnected);
    }

    /** {@return whether a wait of a step was interrupted} (the run should end) */
    public boolean interrupted() {
        return interrupted;
    }

    /** One team step, after the robots were sampled, without the world's lock. */
    private void exchange(SimWorld w) {
        long now = w.timeMs();
        try {
            for (RobotController r : robots) {
                r.sendStep();
            }
            agents.run(now);
            for (RobotController r : robots) {
                r.finishStep();
            }
            afterStep.accept(now);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            interrupted = true;
        }
    }

    /** Closes every robot's controller (each says goodbye). */
    public void close() {
        robots.forEach(RobotController::close);
    }
}
