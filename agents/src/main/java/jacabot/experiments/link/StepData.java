package jacabot.experiments.link;

import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import java.util.List;
import java.util.Optional;

/** One lockstep step as the agent side receives it: the step, its simulated time and its readings. */
public record StepData(long step, long simTimeMs, List<SensorInfo> readings) {
    public StepData {
        readings = List.copyOf(readings);
    }

    /** {@return the reading of a kind in this step, if the controller sent one} */
    public Optional<SensorInfo> reading(SensorKind kind) {
        for (SensorInfo info : readings) {
            if (info.getId() == kind.id()) {
                return Optional.of(info);
            }
        }
        return Optional.empty();
    }

    /** {@return the scalar value of a kind, NaN when absent} */
    public double value(SensorKind kind) {
        return reading(kind).map(SensorInfo::getVal).orElse(Double.NaN);
    }
}
