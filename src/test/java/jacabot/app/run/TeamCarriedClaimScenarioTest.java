package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.experiments.team.TaskBoard;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectState;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Team-delivery's claims (thesis Chapter 6; team-claims.asl, TaskBoard): khepera1 picks up the
 * one cylinder and carries it to the storage point across khepera2's view. khepera2 sees it in the
 * gripper as a red cylinder; the carried cylinder's claim follows khepera1, so khepera2 never holds
 * a claim on it, and the run's ground truth counts no double claim.
 */
class TeamCarriedClaimScenarioTest {
    private static final String WORLD = """
            {
              "name": "team-carry-past",
              "arena": { "width": 1.2, "depth": 1.2, "wallThickness": 0.02, "wallHeight": 0.1 },
              "basicTimeStep": 8, "controlStep": 40, "seed": 5,
              "cylinders": [ { "id": "red1", "x": -0.16, "z": -0.35, "color": "red" } ],
              "storage": { "x": -0.16, "z": 0.45, "radius": 0.06 },
              "charger": { "x": 0.5, "z": -0.5, "radius": 0.06, "power": 20 },
              "robots": [
                { "name": "khepera1", "model": "khepera", "x": -0.16, "z": -0.44, "heading": 90, "battery": 900 },
                { "name": "khepera2", "model": "khepera", "x": 0.45, "z": 0.0, "heading": 180, "battery": 900 }
              ]
            }
            """;
    /** A claim this near the carried cylinder names it, metres (the run's ground truth: TeamWatch). */
    private static final double NAMES_IT = 0.3;

    @Tag("long")
    @Test
    void nobodyClaimsACylinderAnotherRobotCarries() throws Exception {
        SimWorld world = TeamScenarioRun.world(WORLD, "team-carry-past.json");
        List<String> onCarried = new ArrayList<>();
        long[] carriedSteps = {0};
        try (var run = TeamScenarioRun.quiet(world, 5)) {
            run.onStep(t -> {
                if (!"red1".equals(world.supervisor().carried("khepera1"))) {
                    return;
                }
                carriedSteps[0]++;
                ObjectState c = world.supervisor().objects().stream().filter(o -> o.id().equals("red1")).findFirst().orElseThrow();
                for (TaskBoard.Held h : run.board().claims()) {
                    if (h.agent().equals("khepera2") && Math.hypot(h.x() - c.pose().x(), h.z() - c.pose().z()) < NAMES_IT
                            && onCarried.size() < 5) {
                        onCarried.add("t=" + t + " ms: " + h);
                    }
                }
            });
            run.runFor(25);
            assertTrue(run.agentFailure().isEmpty(), () -> "no agent failed: " + run.agentFailure());
            assertTrue(carriedSteps[0] > 100, "khepera1 carried the cylinder for " + carriedSteps[0] + " steps");
            assertEquals(List.of(), onCarried, "khepera2's claims on the cylinder khepera1 carries");
            assertEquals(0, run.watch().doubleClaims(), "double claims by ground truth");
        }
    }
}
