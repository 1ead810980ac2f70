package jacabot.app.sweep;

import jacabot.robot.Experiment;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.List;

/**
 * One run to make: an experiment's controller ({@code agent}, {@code baseline} or {@code equal}) on a world under a
 * seed. {@code file} names the world in messages and reports ({@code spec} is already loaded and
 * checked, its seed not yet replaced); a world the loader rejected has no spec but the loader's
 * {@code problem}, and its runs fail with it.
 */
public record SweepJob(Experiment experiment, String controller, String world, Path file, WorldSpec spec, String problem,
                       long seed) {
    /** The controllers: the agent, the thesis-style baseline, the equal-capability baseline. */
    public static final String AGENT = "agent", BASELINE = "baseline", EQUAL = "equal";
    /** Every controller, in the order of reports. */
    public static final List<String> CONTROLLERS = List.of(AGENT, BASELINE, EQUAL);

    /** {@return a short name, e.g. "navigation navigation-gen-3 agent seed 2"} */
    public String label() {
        return experiment.id() + " " + world + " " + controller + " seed " + seed;
    }
}
