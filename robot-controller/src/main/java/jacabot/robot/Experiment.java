package jacabot.robot;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The four experiments of the thesis' Chapter 4, and tidy-up, a task composed of their skills (not
 * in the thesis): their number, world file, robot and agent. The one list of experiments; the
 * launcher adds each one's middleware artifact.
 */
public enum Experiment {
    /** §1: the two-sensor MyBot wanders and avoids obstacles. */
    OBSTACLE_AVOIDANCE(1, "mybot", "obstacle avoidance with the two-sensor MyBot"),
    /** §2: the Khepera finds and lifts a red cylinder. */
    OBJECT_PICKING(2, "khepera", "red-cylinder picking with the Khepera"),
    /** §3: it brings red cylinders to the storage point with GPS and compass. */
    NAVIGATION(3, "khepera", "navigation to the storage point with GPS and compass"),
    /** §4 and Appendix B: as §3, recharging when the battery runs low. */
    SUSPEND_RESUME(4, "khepera", "task suspend and resume on a low battery (Appendix B)"),
    /**
     * Not in the thesis: every cylinder to the storage area, recharging when needed, then park on the
     * charger; an agent made of the skills of §1-§4 alone, with no procedural baseline.
     */
    TIDY_UP(5, "khepera", "tidy-up: every cylinder to the storage area, then park on the charger (skills of 1-4)");

    /** {@return the four experiments of the thesis' Chapter 4, those with a procedural baseline} */
    public static List<Experiment> thesis() {
        return List.of(OBSTACLE_AVOIDANCE, OBJECT_PICKING, NAVIGATION, SUSPEND_RESUME);
    }

    /** {@return whether the experiment has the thesis' procedural baseline (the C program's counterpart)} */
    public boolean hasBaseline() {
        return this != TIDY_UP;
    }

    /** {@return whether the world has a storage point (experiments 3, 4 and tidy-up)} */
    public boolean needsStorage() {
        return this == NAVIGATION || this == SUSPEND_RESUME || this == TIDY_UP;
    }

    /** {@return whether the world has a charger and the robot a battery that runs low (experiment 4 and tidy-up)} */
    public boolean needsCharger() {
        return this == SUSPEND_RESUME || this == TIDY_UP;
    }

    private final int number;
    private final String robot;
    private final String summary;

    Experiment(int number, String robot, String summary) {
        this.number = number;
        this.robot = robot;
        this.summary = summary;
    }

    /** {@return the section number in Chapter 4} */
    public int number() {
        return number;
    }

    /** {@return one line on what the experiment shows} */
    public String summary() {
        return summary;
    }

    /** {@return the experiment's name in files and on the command line, e.g. "object-picking"} */
    public String id() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** {@return the name of the robot in its world file} */
    public String robot() {
        return robot;
    }

    /** {@return the world file, relative to the project directory} */
    public String worldFile() {
        return "worlds/" + id() + ".json";
    }

    /** {@return the world file of this experiment in a worlds/ directory} */
    public Path worldFile(Path worldsDir) {
        return worldsDir.resolve(id() + ".json");
    }

    /** {@return the agent's source on the class path (packaged with the agents module)} */
    public String agentResource() {
        return "/asl/" + id() + ".asl";
    }

    /** {@return the experiment for a name or number, e.g. "navigation" or "3"} */
    public static Optional<Experiment> parse(String text) {
        for (Experiment e : values()) {
            if (e.id().equals(text) || String.valueOf(e.number).equals(text)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    /** {@return the experiment of that name} @throws IllegalArgumentException when there is none */
    public static Experiment byId(String id) {
        for (Experiment e : values()) {
            if (e.id().equals(id)) {
                return e;
            }
        }
        throw new IllegalArgumentException("unknown experiment '" + id
                + "' (expected obstacle-avoidance, object-picking, navigation, suspend-resume or tidy-up)");
    }

    @Override
    public String toString() {
        return id();
    }
}
