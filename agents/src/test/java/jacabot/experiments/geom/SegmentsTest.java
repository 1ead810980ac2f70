package jacabot.experiments.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Distances between segments: crossing, apart, parallel, points, a point beyond a segment's end. */
class SegmentsTest {
    @Test
    void distancesBetweenSegments() {
        assertEquals(0, Segments.distance(0, 0, 1, 1, 0, 1, 1, 0), 1e-12, "crossing");
        assertEquals(0.5, Segments.distance(0, 0, 1, 0, 0, 0.5, 1, 0.5), 1e-12, "parallel");
        assertEquals(Math.hypot(1, 1), Segments.distance(0, 0, 0, 0, 1, 1, 1, 1), 1e-12, "two points");
        assertEquals(0.3, Segments.distance(0, 0, 1, 0, 0.5, 0.3, 0.5, 0.3), 1e-12, "a point beside the middle");
        assertEquals(Math.hypot(0.5, 0.3), Segments.distance(0, 0, 1, 0, 1.5, 0.3, 1.5, 0.3), 1e-12, "a point beyond the end");
        assertEquals(0.2, Segments.distance(0, 0, 1, 0, 1.2, -1, 1.2, 1), 1e-12, "a T not touching");
        assertEquals(0, Segments.distance(0, 0, 1, 0, 1, 0, 2, 5), 1e-12, "touching ends");
    }
}
