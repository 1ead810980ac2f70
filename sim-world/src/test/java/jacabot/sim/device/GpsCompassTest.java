package jacabot.sim.device;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class GpsCompassTest {
    @Test
    void theGpsGivesXAndZWithAFlatFloor() {
        SimWorld w = TestWorlds.khepera(0.1, -0.2, 30, "");
        Gps gps = w.robot("k").getGps("gps");
        assertTrue(Double.isNaN(gps.getValues()[0]));
        gps.enable(40);
        w.step();
        assertArrayEquals(new double[] {0.1, 0.0, -0.2}, gps.getValues(), 1e-12);
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, 30, 90, 135, 180, 270, 359})
    void theCompassBearingIsTheHeadingAndConvertBearingAgrees(double heading) {
        SimWorld w = TestWorlds.khepera(0, 0, heading, "");
        Compass compass = w.robot("k").getCompass("compass");
        compass.enable(40);
        w.step();
        assertEquals(heading, compass.getBearing(), 1e-9);
        double converted = TestWorlds.convertBearing(compass.getValues());
        double gap = Math.abs(((converted - heading) % 360 + 540) % 360 - 180); // convertBearing uses π/2 ≈ 1.5708
        assertEquals(0.0, gap, 1e-3);
    }

    @Test
    void theCompassValuesPointNorth() {
        SimWorld w = TestWorlds.khepera(0, 0, 90, "");
        Compass compass = w.robot("k").getCompass("compass");
        compass.enable(40);
        w.step();
        assertArrayEquals(new double[] {0, 0, -1}, compass.getValues(), 1e-12);
    }

    @Test
    void facingTheStoragePointFromTheOriginIsBearing315() {
        // storagePoint(0.41, -0.41): north-west of the origin, x north and z east
        double bearing = Math.toDegrees(Math.atan2(-0.41, 0.41));
        SimWorld w = TestWorlds.khepera(0, 0, bearing, "");
        Compass compass = w.robot("k").getCompass("compass");
        compass.enable(40);
        w.robot("k").setSpeeds(100, 100);
        w.step(2000);
        assertEquals(315.0, compass.getBearing(), 1e-9);
        assertEquals(0.1 / Math.sqrt(2), w.robot("k").pose().x(), 1e-9);
        assertEquals(-0.1 / Math.sqrt(2), w.robot("k").pose().z(), 1e-9);
    }
}
