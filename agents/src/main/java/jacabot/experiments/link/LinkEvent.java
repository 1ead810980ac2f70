package jacabot.experiments.link;

import jacabot.robot.link.LinkClock;
import jacabot.robot.link.SensorInfo;

/**
 * What {@link MiddlewareLink#receive()} hands the middleware, one at a time and in arrival order:
 * the thesis' {@code await(data); info = data.getInfo()} generalised to the link's other news.
 */
public sealed interface LinkEvent {
    /** A controller connected and shook hands: {@code connected(true)}. */
    record Connected(String robotName, String worldName, int controlStepMs, boolean lockstep) implements LinkEvent {
    }

    /** The controller went away or was disconnected: {@code connected(false)}. */
    record Disconnected(String reason) implements LinkEvent {
    }

    /**
     * One sensor reading.
     *
     * @param step           the controller's control step
     * @param simTimeMs      the simulated time of the step
     * @param sampledMicros  when the controller sampled it ({@link LinkClock})
     * @param receivedMicros when the link read it off the socket
     */
    record Reading(SensorInfo info, long step, long simTimeMs, long sampledMicros, long receivedMicros) implements LinkEvent {
    }

    /**
     * The end of a step's readings. When {@code awaitsAck} (lockstep) the simulation waits for the
     * step's commands and {@link MiddlewareLink#acknowledge(long)}.
     */
    record StepMarker(long step, long simTimeMs, boolean awaitsAck) implements LinkEvent {
    }

    /** The controller's fail-safe stopped the wheels (the agent side was silent too long). */
    record FailSafe(long simTimeMs, String reason) implements LinkEvent {
    }
}
