package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedOutputStream;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The deserialization filter: only SensorInfo and its arrays, within limits. */
class SensorInfoFilterTest {
    /** A class a hostile peer might send; it must never be instantiated by the middleware. */
    static final class Foreign implements Serializable {
        private static final long serialVersionUID = 1L;
        static volatile boolean built;

        private void readObject(java.io.ObjectInputStream in) throws IOException, ClassNotFoundException {
            built = true;
            in.defaultReadObject();
        }
    }

    /** Writes a batch header announcing one reading, then {@code payload} in its place. */
    private static byte[] batchWith(Object payload) throws IOException {
        var bytes = new ByteArrayOutputStream();
        var out = new ObjectOutputStream(new BufferedOutputStream(bytes));
        out.writeByte(Uplink.BATCH);
        out.writeLong(0);
        out.writeLong(0);
        out.writeLong(0);
        out.writeInt(1);
        out.writeObject(payload);
        out.close();
        return bytes.toByteArray();
    }

    private static ProtocolException rejected(byte[] stream) {
        return assertThrows(ProtocolException.class,
                () -> new SensorDataReader(new ByteArrayInputStream(stream), SensorInfoFilter.Limits.DEFAULT).read());
    }

    @Test
    void aForeignSerializedClassIsRejectedBeforeItIsBuilt() throws IOException {
        var e = rejected(batchWith(new Foreign()));
        assertEquals("rejected by the deserialization filter: class " + Foreign.class.getName()
                + " is not allowed (only SensorInfo)", e.getMessage());
        assertTrue(!Foreign.built, "the foreign object was instantiated");
        e = rejected(batchWith(new java.util.ArrayList<>(List.of(1, 2))));
        assertTrue(e.getMessage().contains("java.util.ArrayList is not allowed"), e.getMessage());
    }

    @Test
    void aHugeArrayIsRejectedBeforeItIsAllocated() throws IOException {
        int huge = SensorInfoFilter.Limits.DEFAULT.maxArrayLength() + 1;
        var e = rejected(batchWith(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[huge])));
        assertEquals("rejected by the deserialization filter: array of " + huge + " elements exceeds the limit of "
                + SensorInfoFilter.Limits.DEFAULT.maxArrayLength(), e.getMessage());
        e = rejected(batchWith(new long[] {1, 2}));
        assertTrue(e.getMessage().contains("array of long is not allowed"), e.getMessage());
    }

    @Test
    void aSensorInfoAtTheLimitPassesAndAStringDoesNot() throws IOException {
        int max = SensorInfoFilter.Limits.DEFAULT.maxArrayLength();
        var batch = (Uplink.Batch) new SensorDataReader(new ByteArrayInputStream(
                batchWith(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[max]))), SensorInfoFilter.Limits.DEFAULT).read();
        assertEquals(max, batch.readings().get(0).getIntValues().length);
        var e = rejected(batchWith("a string"));
        assertEquals("expected a SensorInfo, got java.lang.String", e.getMessage());
    }

    @Test
    void theByteLimitIsPerObjectNotPerStream() throws IOException {
        var limits = new SensorInfoFilter.Limits(1000, 3, 1000, 2000);
        var bytes = new ByteArrayOutputStream();
        var writer = new SensorDataWriter(bytes, 10);
        var reading = new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[100]); // ~850 bytes each
        for (int i = 0; i < 20; i++) { // far more than 2000 bytes in all
            writer.writeStep(new Uplink.Batch(i, 0, 0, List.of(reading)), new Uplink.StepMarker(i, 0, false));
        }
        var reader = new SensorDataReader(new ByteArrayInputStream(bytes.toByteArray()), limits);
        for (int i = 0; i < 40; i++) {
            reader.read();
        }
        var e = assertThrows(ProtocolException.class, () -> new SensorDataReader(new ByteArrayInputStream(
                batchWith(new SensorInfo(1, new double[400]))), limits).read());
        assertTrue(e.getMessage().contains("object larger than 2000 bytes"), e.getMessage());
    }
}
