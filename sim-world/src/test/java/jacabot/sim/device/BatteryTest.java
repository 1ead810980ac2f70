package jacabot.sim.device;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import jacabot.sim.robot.Robot;
import org.junit.jupiter.api.Test;

/** Khepera battery: 0.5 W idle, 2 W for both motors at full speed; a 20 W charger of radius 6 cm at (-0.38, 0.38). */
class BatteryTest {
    static final String CHARGER = "\"charger\": {\"x\": -0.38, \"z\": 0.38, \"radius\": 0.06, \"power\": 20}";

    private static SimWorld world(double x, double z, double energy) {
        return TestWorlds.world("\"robots\": [{\"name\": \"k\", \"model\": \"khepera\", \"x\": " + x + ", \"z\": " + z
                + ", \"battery\": " + energy + "}], " + CHARGER);
    }

    @Test
    void idleAndMotorsDrainTheBattery() {
        SimWorld w = world(0, 0, 500);
        Battery b = w.robot("k").getBattery();
        b.enable(40);
        w.step(10_000);
        assertEquals(500 - 0.5 * 10, b.getValue(), 1e-9);
        w.robot("k").setSpeeds(100, 100);
        w.step(10_000);
        assertEquals(495 - 2.5 * 10, b.getValue(), 1e-9);
        w.robot("k").setSpeeds(50, -50);
        w.step(4_000);
        assertEquals(470 - 1.5 * 4, b.getValue(), 1e-9);
    }

    @Test
    void theChargerRechargesUpToTheMaximum() {
        SimWorld w = world(-0.38, 0.38, 400);
        Battery b = w.robot("k").getBattery();
        b.enable(40);
        w.step(10_000);
        assertEquals(400 + (20 - 0.5) * 10, b.getValue(), 1e-9);
        w.step(40_000);
        assertEquals(1000, b.getValue(), 1e-9);
    }

    @Test
    void anEmptyBatteryStopsTheRobot() {
        SimWorld w = world(0, 0, 1.0);
        Robot k = w.robot("k");
        k.setSpeeds(100, 100);
        w.step(1000);
        assertTrue(k.getBattery().isEmpty());
        double x = k.pose().x();
        assertTrue(x < 0.05 && x > 0.015, "moved until empty: " + x);
        k.setSpeeds(100, 100);
        w.step(1000);
        assertEquals(x, k.pose().x(), 1e-12);
        assertEquals(0.0, k.getWheels().getLeftSpeed());
    }

    @Test
    void theSupervisorDrainsAndSetsTheBattery() {
        SimWorld w = world(0, 0, 600);
        Battery b = w.robot("k").getBattery();
        w.supervisor().drainBattery("k", 150);
        assertEquals(450, b.energy(), 1e-9);
        w.supervisor().setBattery("k", 5000);
        assertEquals(1000, b.energy(), 1e-9);
        w.supervisor().drainBattery("k", 5000);
        assertTrue(b.isEmpty());
    }
}
