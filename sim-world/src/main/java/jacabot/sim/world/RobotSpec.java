package jacabot.sim.world;

/**
 * A robot to place: its unique name, its model ({@code mybot} or {@code khepera}), its pose
 * (metres, heading as a compass bearing in degrees) and, for models with a battery, the initial
 * energy in joules ({@code NaN}: the model's maximum).
 */
public record RobotSpec(String name, String model, double x, double z, double heading, double battery) {
}
