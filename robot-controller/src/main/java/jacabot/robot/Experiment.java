package jacabot.robot;

import java.nio.file.Path;

/** The four experiments of the thesis' Chapter 4, with their world file and robot. */
public enum Experiment {
    /** §1: the two-sensor MyBot wanders and avoids obstacles. */
    OBSTACLE_AVOIDANCE("obstacle-avoidance", "mybot"),
    /** §2: the Khepera finds and lifts a red cylinder. */
    OBJECT_PICKING("object-picking", "khepera"),
    /** §3: it brings red cylinders to the storage point with GPS and compass. */
    NAVIGATION("navigation", "khepera"),
    /** §4 and Appendix B: as §3, recharging when the battery runs low. */
    SUSPEND_RESUME("suspend-resume", "khepera");

    private final String id;
    private final String robot;

    Experiment(String id, String robot) {
        this.id = id;
        this.robot = robot;
    }

    /** {@return the experiment's name in files and on the command line, e.g. "object-picking"} */
    public String id() {
        return id;
    }

    /** {@return the name of the robot in its world file} */
    public String robot() {
        return robot;
    }

    /** {@return the world file of this experiment in a worlds/ directory} */
    public Path worldFile(Path worldsDir) {
        return worldsDir.resolve(id + ".json");
    }

    /** {@return the experiment of that name} @throws IllegalArgumentException when there is none */
    public static Experiment byId(String id) {
        for (Experiment e : values()) {
            if (e.id.equals(id)) {
                return e;
            }
        }
        throw new IllegalArgumentException("unknown experiment '" + id
                + "' (expected obstacle-avoidance, object-picking, navigation or suspend-resume)");
    }
}
