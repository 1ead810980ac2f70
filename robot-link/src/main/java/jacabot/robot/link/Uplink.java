package jacabot.robot.link;

import java.util.List;

/** The frames the controller sends the middleware on the sensor data stream. */
public sealed interface Uplink {
    /** Frame tags on the wire. */
    byte BATCH = 1, STEP_MARKER = 2, APPLIED = 3, FAIL_SAFE = 4, BYE = 5;
    /** Not a frame: the object stream starts again with a new header (bounds both ends' handle tables). */
    byte RESTART = 6;

    /**
     * One control step's readings (one {@link SensorInfo} per enabled device that has a reading),
     * stamped with the simulated time of the step and the wall time they were sampled at.
     */
    record Batch(long step, long simTimeMs, long sampledMicros, List<SensorInfo> readings) implements Uplink {
        public Batch {
            readings = List.copyOf(readings);
        }
    }

    /**
     * The end of a step's data. In lockstep ({@code awaitsAck}) the simulation does not advance
     * until the middleware has sent the step's commands and {@code STEP_ACK(step)}.
     */
    record StepMarker(long step, long simTimeMs, boolean awaitsAck) implements Uplink {
    }

    /** A command took effect on the actuators (or started its manoeuvre) at this step. */
    record Applied(int seq, int code, long step, long simTimeMs, long receivedMicros, long appliedMicros)
            implements Uplink {
    }

    /** The controller stopped the wheels on its own: the agent side went silent. */
    record FailSafe(long simTimeMs, String reason) implements Uplink {
    }

    /** The controller is leaving: the simulation ended or it was stopped ({@code robot.step} = −1). */
    record Bye(String reason) implements Uplink {
    }
}
