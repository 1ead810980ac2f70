package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedOutputStream;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InvalidClassException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The readings' compact encoding (protocol version 3), its limits, and the filter that refuses every object. */
class SensorInfoCodecTest {
    /** A class a hostile peer might send; it must never be instantiated by the middleware. */
    static final class Foreign implements Serializable {
        private static final long serialVersionUID = 1L;
        static volatile boolean built;

        private void readObject(ObjectInputStream in) throws IOException, ClassNotFoundException {
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
        if (payload instanceof SensorInfo) {
            SensorInfoCodec.write(out, (SensorInfo) payload);
        } else {
            out.writeObject(payload);
        }
        out.close();
        return bytes.toByteArray();
    }

    private static ProtocolException rejected(byte[] stream, SensorInfoFilter.Limits limits) {
        return assertThrows(ProtocolException.class, () -> new SensorDataReader(new ByteArrayInputStream(stream), limits).read());
    }

    @Test
    void everyReadingReadsBackEqualEvenTheMalformedOnes() throws IOException {
        List<SensorInfo> readings = new ArrayList<>(LinkFramesTest.everyShape());
        readings.add(new SensorInfo(1, -0.0));
        readings.add(new SensorInfo(2, 0.0));
        readings.add(new SensorInfo(SensorKind.GPS.id(), 0, 0, 0));
        readings.add(new SensorInfo(SensorKind.GPS.id(), 0, Double.NaN, 0));
        readings.add(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[0]));
        readings.add(new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[] {Double.POSITIVE_INFINITY}));
        var bytes = new ByteArrayOutputStream();
        new SensorDataWriter(bytes, 100).writeStep(new Uplink.Batch(0, 0, 0, readings), new Uplink.StepMarker(0, 0, false));
        var batch = (Uplink.Batch) new SensorDataReader(new ByteArrayInputStream(bytes.toByteArray()),
                SensorInfoFilter.Limits.DEFAULT).read();
        assertEquals(readings, batch.readings());
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(batch.readings().get(readings.size() - 6).getVal()));
    }

    @Test
    void aReadingOwningItsArrayIsTheReadingOfACopy() throws IOException {
        int[] image = {4, 2, 0xC81E1E, 0x000000, 0xFFFFFF, 7, 8, 9, 10, 11};
        SensorInfo owning = SensorInfo.owning(SensorKind.CAMERA_IMAGE.id(), image);
        SensorInfo copied = new SensorInfo(SensorKind.CAMERA_IMAGE.id(), image.clone());
        assertEquals(copied, owning);
        assertArrayEquals(image, owning.getIntValues());
        var a = new ByteArrayOutputStream();
        var b = new ByteArrayOutputStream();
        new SensorDataWriter(a, 100).writeStep(new Uplink.Batch(3, 120, 0, List.of(owning)), new Uplink.StepMarker(3, 120, true));
        new SensorDataWriter(b, 100).writeStep(new Uplink.Batch(3, 120, 0, List.of(copied)), new Uplink.StepMarker(3, 120, true));
        assertArrayEquals(b.toByteArray(), a.toByteArray());
    }

    /**
     * The int arrays are written and read in one call each (SensorInfoCodec): the stream's bytes
     * must be those of writing each int, whatever the block boundaries of the object stream.
     */
    @Test
    void anIntArrayGoesOnTheStreamAsItsIntsOneByOneWouldAndReadsBack() throws IOException {
        for (int prefix = 0; prefix < 7; prefix++) {
            for (int n : new int[] {1, 2, 255, 256, 257, 300, 514, 1025}) {
                int[] v = new int[n];
                for (int i = 0; i < n; i++) {
                    v[i] = i * 0x01020304 ^ -i;
                }
                var bulk = new ByteArrayOutputStream();
                var single = new ByteArrayOutputStream();
                try (var a = new ObjectOutputStream(bulk); var b = new ObjectOutputStream(single)) {
                    for (int k = 0; k < prefix * 97; k++) { // move the array across the 1 024-byte blocks
                        a.writeByte(k);
                        b.writeByte(k);
                    }
                    SensorInfoCodec.write(a, new SensorInfo(SensorKind.CAMERA_IMAGE.id(), v));
                    b.writeInt(SensorKind.CAMERA_IMAGE.id());
                    b.writeByte(SensorInfoCodec.INTS);
                    b.writeInt(n);
                    for (int i : v) {
                        b.writeInt(i);
                    }
                }
                assertArrayEquals(single.toByteArray(), bulk.toByteArray(), "prefix " + prefix * 97 + ", " + n + " ints");
                try (var in = new ObjectInputStream(new ByteArrayInputStream(bulk.toByteArray()))) {
                    in.skipBytes(prefix * 97);
                    var read = SensorInfoCodec.read(in, SensorInfoFilter.Limits.DEFAULT, Long.MAX_VALUE);
                    assertArrayEquals(v, read.info().getIntValues());
                    assertEquals(9 + 4L * n, read.bytes());
                }
            }
        }
    }

    @Test
    void imagesOfEverySizeWrittenAndReadThroughOneScratchEachComeBackWholeAndApart() throws IOException {
        int[] sizes = {300, 5, 1_000, 1, 300};
        var bytes = new ByteArrayOutputStream();
        List<int[]> written = new ArrayList<>();
        var writing = new SensorInfoCodec.Scratch();
        try (var out = new ObjectOutputStream(bytes)) {
            for (int k = 0; k < sizes.length; k++) {
                int[] v = new int[sizes[k]];
                for (int i = 0; i < v.length; i++) {
                    v[i] = (k + 1) * 1_000_003 * (i + 7);
                }
                written.add(v);
                SensorInfoCodec.write(out, new SensorInfo(SensorKind.CAMERA_IMAGE.id(), v), writing);
            }
        }
        var scratch = new SensorInfoCodec.Scratch();
        List<SensorInfo> read = new ArrayList<>();
        try (var in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            for (int size : sizes) {
                var d = SensorInfoCodec.read(in, SensorInfoFilter.Limits.DEFAULT, Long.MAX_VALUE, scratch);
                assertEquals(9 + 4L * size, d.bytes());
                read.add(d.info());
            }
        }
        for (int k = 0; k < sizes.length; k++) { // each its own array: a later image did not write over an earlier
            assertArrayEquals(written.get(k), read.get(k).getIntValues(), "image " + k);
            assertArrayEquals(written.get(k), read.get(k).readInts(a -> a.clone()), "image " + k + " lent");
        }
    }

    @Test
    void anObjectInAReadingsPlaceIsNeverBuilt() throws IOException {
        var e = rejected(batchWith(new Foreign()), SensorInfoFilter.Limits.DEFAULT);
        assertTrue(e.getMessage().contains("carried something other than its fields"), e.getMessage());
        assertFalse(Foreign.built, "the foreign object was instantiated");
        e = rejected(batchWith("a string"), SensorInfoFilter.Limits.DEFAULT);
        assertTrue(e.getMessage().startsWith("truncated frame"), e.getMessage());
    }

    @Test
    void theFilterRefusesEveryClassShouldAnythingEverDeserialize() throws IOException {
        var bytes = new ByteArrayOutputStream();
        try (var out = new ObjectOutputStream(bytes)) {
            out.writeObject(new SensorInfo(1, 2.0));
        }
        var filter = new SensorInfoFilter();
        var in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()));
        in.setObjectInputFilter(filter);
        assertThrows(InvalidClassException.class, in::readObject);
        assertEquals("class " + SensorInfo.class.getName() + " is not allowed (the sensor data stream carries no objects)",
                filter.lastRejection());
    }

    @Test
    void aHugeArrayIsRefusedBeforeItIsAllocatedAndOneAtTheLimitPasses() throws IOException {
        int max = SensorInfoFilter.Limits.DEFAULT.maxArrayLength();
        var e = rejected(batchWith(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[max + 1])), SensorInfoFilter.Limits.DEFAULT);
        assertEquals("rejected: array of " + (max + 1) + " elements exceeds the limit of " + max, e.getMessage());
        byte[] announced = batchWith(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[] {1}));
        announced[announced.length - 8] = (byte) 0x7f; // the length's first byte: 2 G elements announced, 1 sent
        e = rejected(announced, SensorInfoFilter.Limits.DEFAULT);
        assertTrue(e.getMessage().startsWith("rejected: array of 21"), e.getMessage());
        var batch = (Uplink.Batch) new SensorDataReader(new ByteArrayInputStream(
                batchWith(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[max]))), SensorInfoFilter.Limits.DEFAULT).read();
        assertEquals(max, batch.readings().get(0).intCount());
    }

    @Test
    void unknownFieldFlagsAreGarbage() throws IOException {
        byte[] stream = batchWith(new SensorInfo(1, 2.0));
        stream[stream.length - 9] = 0x30; // the flags byte, before the 8 bytes of the value
        var e = rejected(stream, SensorInfoFilter.Limits.DEFAULT);
        assertEquals("garbage on the sensor data stream: reading 1 has field flags 48", e.getMessage());
    }

    @Test
    void theByteLimitIsPerReadingNotPerStream() throws IOException {
        var limits = new SensorInfoFilter.Limits(1000, 3, 1000, 2000);
        var bytes = new ByteArrayOutputStream();
        var writer = new SensorDataWriter(bytes, 10);
        var reading = new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[100]); // ~810 bytes each
        for (int i = 0; i < 20; i++) { // far more than 2000 bytes in all
            writer.writeStep(new Uplink.Batch(i, 0, 0, List.of(reading)), new Uplink.StepMarker(i, 0, false));
        }
        var reader = new SensorDataReader(new ByteArrayInputStream(bytes.toByteArray()), limits);
        for (int i = 0; i < 40; i++) {
            reader.read();
        }
        var e = rejected(batchWith(new SensorInfo(1, new double[400])), limits);
        assertEquals("rejected: reading larger than 2000 bytes", e.getMessage());
    }
}
