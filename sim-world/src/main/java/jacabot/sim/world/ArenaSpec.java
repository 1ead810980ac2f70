package jacabot.sim.world;

import jacabot.sim.geom.Rgb;

/**
 * The bounded floor, centred on the origin: x in [-width/2, width/2] (north-south), z in
 * [-depth/2, depth/2] (west-east). Four walls of the given thickness and height stand just outside.
 */
public record ArenaSpec(double width, double depth, double wallThickness, double wallHeight, Rgb floorColor, Rgb wallColor) {
    /** {@return half the width (x extent)} */
    public double halfWidth() {
        return width / 2;
    }

    /** {@return half the depth (z extent)} */
    public double halfDepth() {
        return depth / 2;
    }
}
