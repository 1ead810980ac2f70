package jacabot.sim;

import jacabot.sim.io.WorldFileException;
import java.nio.file.Path;

/** Small worlds for tests: a 1 m × 1 m arena, no sensor noise unless asked, and the given parts. */
public final class TestWorlds {
    private TestWorlds() {
    }

    /** {@return a world from JSON members (without braces) added to a noiseless 1 m arena} */
    public static SimWorld world(String members) {
        return world(members, false);
    }

    /** {@return a world from JSON members, with or without sensor noise} */
    public static SimWorld world(String members, boolean noise) {
        String json = "{ \"arena\": {\"width\": 1.0, \"depth\": 1.0}, \"seed\": 7, \"sensorNoise\": " + noise
                + (members.isBlank() ? "" : ", " + members) + " }";
        try {
            return SimWorld.parse(json, "test");
        } catch (WorldFileException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** {@return a khepera named "k" at a pose, plus other members} */
    public static SimWorld khepera(double x, double z, double heading, String members) {
        String robot = "\"robots\": [{\"name\": \"k\", \"model\": \"khepera\", \"x\": " + x + ", \"z\": " + z
                + ", \"heading\": " + heading + "}]";
        return world(members.isBlank() ? robot : robot + ", " + members);
    }

    /** {@return the repository's worlds/ directory} */
    public static Path worldsDir() {
        String root = System.getProperty("jacabot.rootDir");
        return (root == null ? Path.of("..") : Path.of(root)).resolve("worlds");
    }

    /** {@return the thesis' convertBearing: compass values to degrees} */
    public static double convertBearing(double[] v) {
        double rad = Math.atan2(v[0], v[2]);
        double bearing = (rad - 1.5708) / Math.PI * 180.0;
        return bearing < 0 ? bearing + 360 : bearing;
    }
}
