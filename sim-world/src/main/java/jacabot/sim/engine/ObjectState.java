package jacabot.sim.engine;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Pose;

/**
 * A snapshot of one object: id, kind, pose, full sizes along its own x and z axes (a cylinder's
 * diameter twice, a robot's too), height and colour, whether it can move, and the robot carrying
 * it (null when none).
 */
public record ObjectState(String id, ObjectKind kind, Pose pose, double sizeX, double sizeZ, double height, Rgb color,
                          boolean movable, String carriedBy) {
}
