package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.geom.Pose;
import jacabot.sim.robot.Robot;
import jacabot.sim.world.AreaSpec;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Team-delivery's coordination at the storage point (thesis Chapter 6; team-storage.asl): two
 * robots each pick up the cylinder in front of them at once and bring it to the one storage point;
 * the task board gives them turns, so that they are never both at the storage point, never touch
 * each other, and both deliver.
 */
class TeamStorageTurnScenarioTest {
    /** Two robots side by side, a cylinder 9 cm ahead of each, the storage point 0.45 m on. */
    private static final String WORLD = """
            {
              "name": "team-storage-turns",
              "arena": { "width": 1.2, "depth": 1.2, "wallThickness": 0.02, "wallHeight": 0.1 },
              "basicTimeStep": 8, "controlStep": 40, "seed": 5,
              "cylinders": [
                { "id": "red1", "x": -0.16, "z": -0.21, "color": "red" },
                { "id": "red2", "x": 0.16, "z": -0.21, "color": "red" }
              ],
              "storage": { "x": 0.0, "z": 0.35, "radius": 0.06 },
              "charger": { "x": -0.5, "z": -0.5, "radius": 0.06, "power": 20 },
              "robots": [
                { "name": "khepera1", "model": "khepera", "x": -0.16, "z": -0.3, "heading": 90, "battery": 900 },
                { "name": "khepera2", "model": "khepera", "x": 0.16, "z": -0.3, "heading": 90, "battery": 900 }
              ]
            }
            """;
    private static final double SECONDS = 70;
    /** The middleware's storage access radius: a robot this near the storage point is at it. */
    private static final double AT_STORAGE = 0.15;

    @Test
    void twoRobotsDeliverInTurnsWithoutTouching() throws Exception {
        SimWorld world = TeamScenarioRun.world(WORLD, "team-storage-turns.json");
        List<String> together = new ArrayList<>();
        AreaSpec storage = world.spec().storage();
        try (var run = TeamScenarioRun.quiet(world, 5)) {
            run.onStep(t -> {
                List<Robot> at = world.robots().stream().filter(r -> {
                    Pose p = r.pose();
                    return Math.hypot(p.x() - storage.x(), p.z() - storage.z()) < AT_STORAGE;
                }).toList();
                if (at.size() > 1 && together.size() < 5) {
                    together.add("t=" + t + " ms"); // the first few
                }
            });
            run.runFor(SECONDS);
            assertTrue(run.agentFailure().isEmpty(), () -> "no agent failed: " + run.agentFailure());
        }
        assertEquals(List.of(), together, "both robots at the storage point (the first steps)");
        for (Robot r : world.robots()) {
            assertTrue(r.robotContactTime() == 0, r.name() + " touched the other robot for " + r.robotContactTime() + " s");
        }
        assertEquals(2, storedCount(world), "both cylinders put down at the storage point");
    }

    private static long storedCount(SimWorld world) {
        AreaSpec s = world.spec().storage();
        return world.supervisor().objects().stream()
                .filter(o -> o.id().startsWith("red") && Math.hypot(o.pose().x() - s.x(), o.pose().z() - s.z()) < AT_STORAGE).count();
    }
}
