package jacabot.sim.device;

import java.util.function.LongSupplier;

/** Base of the sampled sensors: name, the enable/disable/period triad, and a reading per period. */
public abstract class Sensor implements Device {
    private final String name;
    private final Sampling sampling;

    protected Sensor(String name, LongSupplier clock) {
        this.name = name;
        this.sampling = new Sampling(clock);
    }

    @Override
    public final String name() {
        return name;
    }

    /** Enables the sensor: the first reading comes {@code samplingPeriodMs} ms later. */
    public void enable(int samplingPeriodMs) {
        sampling.enable(samplingPeriodMs);
    }

    /** Disables the sensor; its value becomes NaN. */
    public void disable() {
        sampling.disable();
    }

    /** {@return the sampling period in ms, 0 when disabled} */
    public int getSamplingPeriod() {
        return sampling.period();
    }

    /** {@return whether a reading is available} */
    public boolean hasValue() {
        return sampling.ready();
    }

    /** Called by the world after each physics step: takes a reading when one is due. */
    public final void tick(long nowMs) {
        if (sampling.due(nowMs)) {
            sample();
        }
    }

    /** Takes a reading. */
    protected abstract void sample();
}
