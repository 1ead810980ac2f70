package jacabot.sim.world;

/**
 * A scripted world event: when {@link #trigger()} holds, wait {@link #after()} seconds of simulated
 * time, then perform {@link #action()} once.
 */
public record EventSpec(Trigger trigger, double after, Action action) {

    /** When an event fires. */
    public sealed interface Trigger permits At, Near {
    }

    /** At a simulated time, in seconds. */
    public record At(double seconds) implements Trigger {
    }

    /**
     * When an object comes within {@code within} metres (centre to centre) of a robot: the way to
     * say "after the robot detects the cylinder".
     */
    public record Near(String robot, String object, double within) implements Trigger {
    }

    /** What an event does. */
    public sealed interface Action permits Move, AddBox, AddCylinder, Remove, Knock, Drain {
    }

    /** Moves an object or a robot; a {@code NaN} heading keeps the current one. */
    public record Move(String object, double x, double z, double heading) implements Action {
    }

    /** Adds a box. */
    public record AddBox(BoxSpec box) implements Action {
    }

    /** Adds a cylinder. */
    public record AddCylinder(CylinderSpec cylinder) implements Action {
    }

    /** Removes an object. */
    public record Remove(String object) implements Action {
    }

    /** Knocks the cylinder a robot carries out of its gripper. */
    public record Knock(String robot) implements Action {
    }

    /** Drains a robot's battery by an amount of energy, in joules. */
    public record Drain(String robot, double amount) implements Action {
    }
}
