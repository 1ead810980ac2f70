package jacabot.robot.baseline;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The equal baseline's obstacle levels follow the arena's area as coverage.asl's do. */
class EqualObstacleLevelsTest {
    @TempDir
    Path dir;

    /** Obstacle avoidance's world with its arena made {@code side} metres square. */
    private EqualObstacleAvoidanceBaseline inArena(double side) throws Exception {
        Path original = Experiment.OBSTACLE_AVOIDANCE.worldFile(BaselinesTest.worlds());
        String text = Files.readString(original).replaceFirst("\"width\": 1.0, \"depth\": 1.0",
                "\"width\": " + side + ", \"depth\": " + side);
        assertTrue(text.contains("\"width\": " + side), "the world file's arena line changed: " + original);
        Path world = dir.resolve("arena-" + side + ".json");
        Files.writeString(world, text);
        return new EqualObstacleAvoidanceBaseline(BaselineRunner.load(world, 1), Experiment.OBSTACLE_AVOIDANCE.robot(), 1, l -> { });
    }

    @Test
    void inAnArenaOfFiveSquareMetresADifferenceSignalsOnlyOver200AndClearsUnder190() throws Exception {
        EqualObstacleAvoidanceBaseline big = inArena(2.3), middle = inArena(2.0);
        // a difference of 210, both under the safe level (300): an obstacle in the big arena only
        assertTrue(big.signalled(290, 80));
        assertFalse(middle.signalled(290, 80), "between 2 and 5 m2, both sensors safe clear it");
        // a difference of 180 with one sensor between safe and warning: over 150, not over 200
        assertTrue(middle.signalled(310, 130));
        assertFalse(big.signalled(310, 130));
        // a difference of 195, both safe: still not clear in the big arena, clear in the other
        assertFalse(big.clear(245, 50));
        assertTrue(middle.clear(245, 50));
        assertTrue(big.clear(235, 50), "a difference of 185");
        // a sensor past the warning level signals in both
        assertTrue(big.signalled(500, 450) && middle.signalled(500, 450));
    }
}
