package jacabot.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.device.DistanceSensor;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.robot.Robot;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Same world file and seed, same run, to the bit: trajectories and noisy readings. */
class DeterminismTest {
    /** Wanders with a sensor-driven avoidance for 60 s, pushing into walls and boxes; returns the readings. */
    static List<Double> run(SimWorld w) {
        Robot k = w.robot("khepera");
        DistanceSensor left = k.getDistanceSensor("front-left"), right = k.getDistanceSensor("front-right"),
                front = k.getDistanceSensor("front");
        for (DistanceSensor d : List.of(left, right, front)) {
            d.enable(w.controlStep());
        }
        List<Double> readings = new ArrayList<>();
        for (int i = 0; i < 1500; i++) {
            w.step();
            double l = left.getValue(), r = right.getValue(), f = front.getValue();
            readings.add(l + 1e3 * r + 1e6 * f);
            if (f > 350 || l > 350 || r > 350) {
                k.setSpeeds(l > r ? 60 : -60, l > r ? -60 : 60);
            } else {
                k.setSpeeds(100, 100 - (i / 50 % 3) * 30);
            }
        }
        return readings;
    }

    @Test
    void twoRunsOfTheSameWorldAreIdentical() throws WorldFileException {
        SimWorld a = SimWorld.load(TestWorlds.worldsDir().resolve("object-picking.json"));
        SimWorld b = SimWorld.load(TestWorlds.worldsDir().resolve("object-picking.json"));
        List<Double> ra = run(a), rb = run(b);
        assertEquals(ra, rb);
        assertEquals(a.robot("khepera").trajectory(), b.robot("khepera").trajectory());
        assertEquals(a.robot("khepera").contactTime(), b.robot("khepera").contactTime());
        assertEquals(a.supervisor().objects(), b.supervisor().objects());
        assertTrue(a.robot("khepera").trajectory().size() == 1501);
    }

    @Test
    void anotherSeedChangesTheNoise() throws WorldFileException {
        String json = "{\"seed\": %d, \"robots\": [{\"name\": \"khepera\", \"model\": \"khepera\"}],"
                + " \"boxes\": [{\"x\": 0.07, \"z\": 0, \"size\": 0.04}]}";
        SimWorld a = SimWorld.parse(String.format(json, 1), "a"), b = SimWorld.parse(String.format(json, 2), "b");
        assertNotEquals(run(a), run(b));
    }
}
