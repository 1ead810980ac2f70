package jacabot.app.world;

import jacabot.robot.Experiment;
import jacabot.sim.world.WorldSpec;
import java.util.Optional;

/**
 * The landmarks an experiment needs in its world (Chapter 4 §3-4): navigation a storage point,
 * suspend/resume and tidy-up a storage point and a charger; and the robot the experiment drives. Checked before
 * a run starts, for the agent and the baseline alike.
 */
public final class Landmarks {
    private Landmarks() {
    }

    /** {@return one line naming the file and the missing entry, or empty when the world has what the experiment needs} */
    public static Optional<String> missing(Experiment experiment, WorldSpec spec, String file) {
        String needs = "the " + experiment.id() + " experiment needs ";
        if (spec.robots().stream().noneMatch(r -> r.name().equals(experiment.robot()))) {
            return Optional.of(file + ": $.robots: " + needs + "a robot named '" + experiment.robot() + "'; the world has "
                    + (spec.robots().isEmpty() ? "none" : "only " + String.join(", ", spec.robots().stream().map(r -> r.name()).toList())));
        }
        if (experiment.needsStorage() && spec.storage() == null) {
            return Optional.of(file + ": $.storage: " + needs + "a storage point; the world has none");
        }
        if (experiment.needsCharger() && spec.charger() == null) {
            return Optional.of(file + ": $.charger: " + needs + "a charger; the world has none");
        }
        return Optional.empty();
    }
}
