package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class FlankMemoryTest {
    /** 2 s memory, 6.5 cm reach, the side bent towards clear for 10 cm, 12 cm ahead. */
    private final FlankMemory memory = new FlankMemory(2000, 0.065, 0.10, 0.12);

    @Test
    void aBoxMetWhileAvoidingOnTheLeftBendsRight() {
        memory.add(0, 0.05, 0.05, true); // 5 cm ahead, 5 cm to the left of a robot at the origin heading +x
        double k = memory.bend(100, 0, 0, 0);
        assertEquals(2 * (0.065 - 0.05) / (0.05 * 0.05), k, 1e-9);
        assertTrue(memory.bend(100, 0, 0, 180) == 0, "heading the other way, the point is behind");
    }

    @Test
    void aPointOnTheRightBendsLeftAndNearerPointsBendMore() {
        memory.add(0, 0.08, -0.05, true);
        double far = memory.bend(0, 0, 0, 0);
        assertTrue(far < 0, "bend left, got " + far);
        double near = memory.bend(0, 0.04, 0, 0);
        assertTrue(near < far, "nearer ahead, a sharper bend: " + near + " against " + far);
    }

    @Test
    void pointsOutOfTheStripOrNotMetWhileAvoidingAskNoBend() {
        memory.add(0, 0.05, 0.08, true);  // beyond the reach
        memory.add(0, 0.20, 0.01, true);  // beyond the length
        memory.add(0, 0.05, 0.03, false); // in the strip, but met on a straight leg
        assertEquals(0, memory.bend(0, 0, 0, 0));
    }

    @Test
    void noBendTowardsASideWithAPointSeenAndNoneAfterTheMemoryEnds() {
        memory.add(0, 0.05, 0.05, true);
        memory.add(0, 0.06, -0.09, false); // a box at the right, seen less closely
        assertEquals(0, memory.bend(0, 0, 0, 0));
        FlankMemory alone = new FlankMemory(2000, 0.065, 0.10, 0.12);
        alone.add(0, 0.05, 0.05, true);
        assertTrue(alone.bend(1999, 0, 0, 0) > 0);
        assertEquals(0, alone.bend(2001, 0, 0, 0));
    }
}
