package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Team-delivery's charger (thesis Chapter 6; team-charger.asl, ChargerQueue): three robots start
 * with low batteries, the neediest farthest from the charger, the least needy nearest. The nearest
 * asks first, finds the charger free and takes it; the other two book their places while it
 * charges. The queue is ordered by need, so the farthest, neediest robot charges next; a
 * first-come queue (robots queueing as they arrive near the charger) gives it to the nearer one.
 * Nobody touches another robot for 2 s, and no robot waits at the charger behind another for
 * 60 s or more (TeamWatch: arrived at the charger and queued behind another; the robots waiting
 * there go before the booked ones). A booked robot works on meanwhile, here searching beside the
 * charger: TeamWatch counted that as waiting until it asked the queue who had arrived (85 s).
 * 150 simulated seconds: a booked robot works on until its reserve, so the third charge begins
 * about 100-120 s in (it began at 103 s before the step aside, at 120 s after it).
 */
class TeamChargerOrderScenarioTest {
    /** Three robots on a line towards the charger in the corner; no cylinders. */
    private static final String WORLD = """
            {
              "name": "team-charger-order",
              "arena": { "width": 1.4, "depth": 1.4, "wallThickness": 0.02, "wallHeight": 0.1 },
              "basicTimeStep": 8, "controlStep": 40, "seed": 3,
              "cylinders": [],
              "storage": { "x": 0.55, "z": 0.55, "radius": 0.06 },
              "charger": { "x": -0.55, "z": -0.55, "radius": 0.06, "power": 20 },
              "robots": [
                { "name": "khepera1", "model": "khepera", "x": -0.25, "z": -0.45, "heading": 180, "battery": 470 },
                { "name": "khepera2", "model": "khepera", "x": 0.05, "z": -0.25, "heading": 180, "battery": 420 },
                { "name": "khepera3", "model": "khepera", "x": 0.35, "z": 0.05, "heading": 180, "battery": 330 }
              ]
            }
            """;
    private static final double SECONDS = 150;
    /** The task the agents are told of: a team run's 10 minutes, longer than the 150 s watched (told
     *  the run's end, every robot's battery but the neediest's covers it, and only that one charges). */
    private static final double TASK_SECONDS = 600;

    @Tag("long")
    @Test
    void afterTheFirstTheNeediestRobotChargesNext() throws Exception {
        SimWorld world = TeamScenarioRun.world(WORLD, "team-charger-order.json");
        Map<String, Double> last = new HashMap<>();
        List<String> charged = new ArrayList<>(); // the robots in the order their batteries first rose
        Map<String, Double> waited = new HashMap<>();
        try (var run = TeamScenarioRun.quiet(world, 3)) {
            run.onStep(t -> {
                for (Robot r : world.robots()) {
                    double e = r.getBattery().energy();
                    Double before = last.put(r.name(), e);
                    if (before != null && e > before + 1e-6 && !charged.contains(r.name())) {
                        charged.add(r.name());
                    }
                }
            });
            run.tellTaskEnd(TASK_SECONDS);
            run.runFor(SECONDS);
            assertTrue(run.agentFailure().isEmpty(), () -> "no agent failed: " + run.agentFailure());
            for (Robot r : world.robots()) {
                waited.put(r.name(), run.watch().longestChargerWait(r.name()));
            }
        }
        assertEquals(List.of("khepera1", "khepera3", "khepera2"), charged, "the first to ask, then by need");
        for (Robot r : world.robots()) {
            assertTrue(r.robotContactTime() < 2, r.name() + " touched another robot for " + r.robotContactTime() + " s");
            assertTrue(waited.get(r.name()) < 60, r.name() + " waited at the charger for " + waited.get(r.name()) + " s");
        }
    }
}
