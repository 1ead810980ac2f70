package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import org.junit.jupiter.api.Test;

class SensorInfoTest {
    private static SensorInfo roundTrip(SensorInfo info) throws Exception {
        var bytes = new ByteArrayOutputStream();
        try (var out = new ObjectOutputStream(bytes)) {
            out.writeObject(info);
        }
        try (var in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            return (SensorInfo) in.readObject();
        }
    }

    @Test
    void everyShapeSurvivesJavaSerialization() throws Exception {
        var scalar = roundTrip(new SensorInfo(1, 352.5));
        assertEquals(1, scalar.getId());
        assertEquals(352.5, scalar.getVal());

        var rgb = roundTrip(new SensorInfo(2, new int[] {200, 40, 30}));
        assertArrayEquals(new int[] {200, 40, 30}, rgb.getIntValues());

        var gps = roundTrip(new SensorInfo(3, 0.41, 0.0, -0.41));
        assertArrayEquals(new double[] {0.41, 0.0, -0.41}, gps.getCoord());

        var array = roundTrip(new SensorInfo(4, new double[] {1.5, 2.5}));
        assertEquals(4, array.getId(), "the thesis' double-array constructor lost the id; ours keeps it");
        assertArrayEquals(new double[] {1.5, 2.5}, array.getDoubleValues());
    }
}
