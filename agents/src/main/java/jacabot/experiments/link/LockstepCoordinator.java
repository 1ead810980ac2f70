package jacabot.experiments.link;

import jacabot.robot.ControllerConfig;
import jacabot.robot.Readings;
import jacabot.robot.link.Command;
import jacabot.robot.link.SensorInfo;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * Runs a world in lockstep with an agent side, over the real socket protocol (an
 * {@link InProcessLink}). Each control step: the controller sends the step's readings and a step
 * marker; the coordinator hands them to the {@link AgentSide} (deliver, reason until quiescent,
 * collect the actions), sends the returned commands and {@code STEP_ACK}; only then does the world
 * advance. Same world, agent and seed ⇒ the same run, to the byte of both event logs.
 *
 * <pre>{@code
 * var run = new LockstepCoordinator(SimWorld.load(path), "khepera", data -> {
 *     clock.set(data.simTimeMs());            // the agents' SimulatedClock follows the world
 *     artifact.deliver(data.readings());
 *     mas.runUntilQuiescent(1000);
 *     return artifact.takeCommands();
 * }).runFor(30);
 * }</pre>
 */
public final class LockstepCoordinator {
    /** The agent platform's side of one step. */
    @FunctionalInterface
    public interface AgentSide {
        /** Delivers the step's readings, runs the agents until quiescent, {@return the commands to send} */
        List<Command> step(StepData data) throws Exception;
    }

    /** What a run leaves: its steps, the controller's and the agent side's event logs, the timings. */
    public record Result(long steps, List<String> controllerLog, List<String> agentLog, LatencyStats response,
                         List<String> linkLog) {
        /** {@return both logs as one text, controller first (what two runs must agree on)} */
        public String eventLog() {
            return String.join("\n", controllerLog) + "\n--\n" + String.join("\n", agentLog) + "\n";
        }
    }

    /** Safety net: a controller silent this long is broken, not slow. */
    private static final long SILENCE_LIMIT_SECONDS = 60;

    private final SimWorld world;
    private final String robotName;
    private final AgentSide agent;

    /** @param robotName the robot to control, null for the world's first */
    public LockstepCoordinator(SimWorld world, String robotName, AgentSide agent) {
        this.world = world;
        this.robotName = robotName;
        this.agent = agent;
    }

    /**
     * Runs {@code seconds} of simulated time.
     *
     * @throws IOException when the link cannot be opened
     * @throws IllegalStateException when the agent side fails or the controller falls silent
     */
    public Result runFor(double seconds) throws IOException, InterruptedException {
        List<String> controllerLog = Collections.synchronizedList(new ArrayList<>());
        List<String> agentLog = new ArrayList<>();
        List<String> linkLog = Collections.synchronizedList(new ArrayList<>());
        Consumer<String> log = linkLog::add;
        ControllerConfig cc = ControllerConfig.defaults().withRobot(robotName).withLockstep(true).withLog(log)
                .withEventLog(controllerLog::add);
        try (InProcessLink link = InProcessLink.start(world, cc, LinkConfig.defaults().withLog(log))) {
            Throwable[] simFailure = new Throwable[1];
            Thread simulation = new Thread(() -> {
                try {
                    link.controller().runner().runFor(seconds);
                } catch (RuntimeException | Error e) {
                    simFailure[0] = e;
                } finally {
                    link.controller().close(); // says goodbye: the agent loop ends
                }
            }, "lockstep-simulation");
            simulation.setDaemon(true);
            simulation.start();
            long steps;
            try {
                steps = serve(link.middleware(), agentLog);
            } finally {
                link.controller().close();
                simulation.join(TimeUnit.SECONDS.toMillis(SILENCE_LIMIT_SECONDS));
            }
            if (simFailure[0] != null) {
                throw new IllegalStateException("the simulation failed: " + simFailure[0], simFailure[0]);
            }
            return new Result(steps, List.copyOf(controllerLog), List.copyOf(agentLog), link.middleware().timings().response(),
                    List.copyOf(linkLog));
        }
    }

    /** The agent side's loop: collect a step's readings, call the agent at its marker, answer. */
    private long serve(MiddlewareLink link, List<String> agentLog) throws InterruptedException {
        List<SensorInfo> readings = new ArrayList<>();
        long steps = 0;
        boolean connectedOnce = false;
        while (true) {
            LinkEvent e = link.poll(SILENCE_LIMIT_SECONDS, TimeUnit.SECONDS);
            if (e == null) {
                throw new IllegalStateException("no data from the controller for " + SILENCE_LIMIT_SECONDS + " s");
            }
            if (e instanceof LinkEvent.Connected) {
                connectedOnce = true;
                readings.clear();
            } else if (e instanceof LinkEvent.Reading) {
                readings.add(((LinkEvent.Reading) e).info());
            } else if (e instanceof LinkEvent.StepMarker) {
                LinkEvent.StepMarker m = (LinkEvent.StepMarker) e;
                List<Command> commands = callAgent(new StepData(m.step(), m.simTimeMs(), readings));
                agentLog.add(describe(m, readings, commands));
                readings.clear();
                for (Command c : commands) {
                    link.send(c);
                }
                link.acknowledge(m.step());
                steps++;
            } else if (e instanceof LinkEvent.Disconnected && connectedOnce) {
                return steps; // the controller said goodbye (or dropped: nothing more will come)
            }
        }
    }

    private List<Command> callAgent(StepData data) {
        try {
            List<Command> commands = agent.step(data);
            return commands == null ? List.of() : commands;
        } catch (Exception e) {
            throw new IllegalStateException("the agent side failed at step " + data.step() + ": " + e.getMessage(), e);
        }
    }

    private static String describe(LinkEvent.StepMarker m, List<SensorInfo> readings, List<Command> commands) {
        StringBuilder sb = new StringBuilder("step ").append(m.step()).append(" t=").append(m.simTimeMs());
        for (SensorInfo info : readings) {
            sb.append(' ').append(Readings.format(info));
        }
        sb.append(" -> ").append(commands);
        return sb.toString();
    }
}
