package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The kept directions are those formed afresh, to the bit, whatever the bearings before: a pool of
 * bearings three times the table's slots, asked in random order, so that bearings share slots
 * and replace each other, and the same bearing comes back after it was replaced.
 */
class BeamDirectionsTest {
    @Test
    void aKeptDirectionIsTheOneFormedAfresh() {
        var rnd = new Random(7);
        double[] pool = new double[3000];
        for (int i = 0; i < pool.length; i++) {
            pool[i] = i % 10 == 0 ? Math.rint(rnd.nextDouble() * 720 - 360) : rnd.nextDouble() * 1440 - 720;
        }
        pool[1] = 0.0;
        pool[2] = -0.0;
        var directions = new BeamDirections();
        double[] v = directions.values();
        int repeats = 0;
        boolean[] asked = new boolean[pool.length];
        for (int n = 0; n < 200_000; n++) {
            int i = rnd.nextInt(pool.length);
            repeats += asked[i] ? 1 : 0;
            asked[i] = true;
            double b = pool[i];
            int at = directions.of(b);
            double r = Math.toRadians(b), c = Math.cos(r), s = Math.sin(r), inverse = 1.0 / Math.sqrt(c * c + s * s);
            String where = "bearing " + b + " (ask " + n + ")";
            assertEquals(Double.doubleToRawLongBits(r), Double.doubleToRawLongBits(v[at + BeamDirections.RADIANS]), where);
            assertEquals(Double.doubleToRawLongBits(c), Double.doubleToRawLongBits(v[at + BeamDirections.COS]), where);
            assertEquals(Double.doubleToRawLongBits(s), Double.doubleToRawLongBits(v[at + BeamDirections.SIN]), where);
            assertEquals(Double.doubleToRawLongBits(c * inverse), Double.doubleToRawLongBits(v[at + BeamDirections.DX]), where);
            assertEquals(Double.doubleToRawLongBits(s * inverse), Double.doubleToRawLongBits(v[at + BeamDirections.DY]), where);
        }
        assertTrue(repeats > 150_000, repeats + " bearings asked again");
    }
}
