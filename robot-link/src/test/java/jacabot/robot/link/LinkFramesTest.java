package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The wire formats of both directions, the handshake, and what garbage does to them. */
class LinkFramesTest {
    private static final LinkClock CLOCK = () -> 42;

    /** One reading of every registered kind, in its shape, plus an id this version does not know. */
    static List<SensorInfo> everyShape() {
        List<SensorInfo> all = new ArrayList<>();
        for (SensorKind k : SensorKind.values()) {
            switch (k.shape()) {
                case SCALAR: all.add(new SensorInfo(k.id(), 100.0 + k.id())); break;
                case COORD: all.add(new SensorInfo(k.id(), 0.41, 0.0, -0.41 * k.id())); break;
                case INTS: all.add(new SensorInfo(k.id(), new int[] {255, 0, 3, k.id()})); break;
                default: all.add(new SensorInfo(k.id(), new double[] {1.5, -2.5, k.id()})); break;
            }
        }
        all.add(new SensorInfo(999, Double.NaN));
        return all;
    }

    @Test
    void everySensorInfoShapeSurvivesTheSensorDataStream() throws IOException {
        var bytes = new ByteArrayOutputStream();
        var writer = new SensorDataWriter(bytes, 2);
        List<SensorInfo> readings = everyShape();
        for (int step = 0; step < 5; step++) { // several batches: across the periodic reset()
            writer.writeStep(new Uplink.Batch(step, 40L * step, 7, readings), new Uplink.StepMarker(step, 40L * step, true));
        }
        writer.writeApplied(new Uplink.Applied(3, 1, 4, 160, 10, 20));
        writer.writeFailSafe(new Uplink.FailSafe(200, "silence"));
        writer.writeBye(new Uplink.Bye("done"));
        var reader = new SensorDataReader(new ByteArrayInputStream(bytes.toByteArray()), SensorInfoFilter.Limits.DEFAULT);
        for (int step = 0; step < 5; step++) {
            assertEquals(new Uplink.Batch(step, 40L * step, 7, readings), reader.read());
            assertEquals(new Uplink.StepMarker(step, 40L * step, true), reader.read());
        }
        assertEquals(new Uplink.Applied(3, 1, 4, 160, 10, 20), reader.read());
        assertEquals(new Uplink.FailSafe(200, "silence"), reader.read());
        assertEquals(new Uplink.Bye("done"), reader.read());
        assertNull(reader.read(), "end of stream between frames is a clean close");
    }

    static Command sample(CommandCode code) {
        double[] args = new double[code.arity()];
        for (int i = 0; i < args.length; i++) {
            args[i] = code == CommandCode.CLOSE_GRIP ? 0.7 : (i + 1) * 12.5 * (i % 2 == 0 ? 1 : -1);
        }
        return Command.of(code, args);
    }

    @Test
    void everyCommandSurvivesTheCommandStream() throws IOException {
        var bytes = new ByteArrayOutputStream();
        var writer = new CommandWriter(bytes);
        int seq = 0;
        for (CommandCode code : CommandCode.values()) {
            writer.write(seq++, 1000 + seq, sample(code));
        }
        var reader = new CommandReader(new ByteArrayInputStream(bytes.toByteArray()), CLOCK);
        seq = 0;
        for (CommandCode code : CommandCode.values()) {
            ReceivedCommand rc = reader.read();
            assertTrue(rc.isValid(), rc.skipped());
            assertEquals(sample(code), rc.command());
            assertEquals(seq++, rc.seq());
            assertEquals(42, rc.receivedMicros());
        }
        assertNull(reader.read());
    }

    @Test
    void commandCodesAreUniqueAndNamedAfterTheThesisOperations() {
        var codes = Arrays.stream(CommandCode.values()).mapToInt(CommandCode::code).distinct().count();
        assertEquals(CommandCode.values().length, codes);
        assertEquals("setSpeeds(50.0,-10.0)", Command.setSpeeds(50, -10).toString());
        assertEquals("turnAround", Command.turnAround().toString());
        assertThrows(IllegalArgumentException.class, () -> Command.of(CommandCode.SET_SPEEDS, 1));
        assertThrows(IllegalArgumentException.class, () -> Command.setSpeeds(Double.NaN, 0));
        var ids = Arrays.stream(SensorKind.values()).mapToInt(SensorKind::id).distinct().count();
        assertEquals(SensorKind.values().length, ids);
    }

    private static byte[] frame(int code, int seq, double... args) throws IOException {
        var bytes = new ByteArrayOutputStream();
        var out = new DataOutputStream(bytes);
        out.writeInt(code);
        out.writeInt(seq);
        out.writeLong(0);
        out.writeInt(args.length);
        for (double a : args) {
            out.writeDouble(a);
        }
        return bytes.toByteArray();
    }

    private static byte[] concat(byte[]... parts) {
        var out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }

    @Test
    void unknownCodesAndBadArgumentsAreSkippedAndTheStreamStaysInStep() throws IOException {
        byte[] bytes = concat(frame(999, 1, 1, 2), frame(CommandCode.SET_SPEEDS.code(), 2, 5),
                frame(CommandCode.SET_SPEEDS.code(), 3, Double.POSITIVE_INFINITY, 0), frame(CommandCode.STOP.code(), 4));
        var reader = new CommandReader(new ByteArrayInputStream(bytes), CLOCK);
        ReceivedCommand unknown = reader.read();
        assertFalse(unknown.isValid());
        assertEquals("unknown command code 999", unknown.skipped());
        assertTrue(reader.read().skipped().contains("takes 2 argument(s), got 1"));
        assertTrue(reader.read().skipped().contains("finite"));
        assertEquals(Command.stop(), reader.read().command());
    }

    @Test
    void garbageAndTruncatedCommandFramesAreProtocolErrors() throws IOException {
        byte[] garbage = concat(frame(1, 1), new byte[0]);
        garbage[19] = 100; // argc 100
        var e = assertThrows(ProtocolException.class,
                () -> new CommandReader(new ByteArrayInputStream(garbage), CLOCK).read());
        assertTrue(e.getMessage().startsWith("garbage on the command stream"), e.getMessage());
        byte[] whole = frame(CommandCode.SET_SPEEDS.code(), 1, 1, 2);
        byte[] truncated = Arrays.copyOf(whole, whole.length - 3);
        e = assertThrows(ProtocolException.class, () -> new CommandReader(new ByteArrayInputStream(truncated), CLOCK).read());
        assertTrue(e.getMessage().startsWith("truncated command frame"), e.getMessage());
    }

    @Test
    void randomBytesNeverEscapeAsAnythingButProtocolErrors() {
        Random random = new Random(6);
        for (int i = 0; i < 300; i++) {
            byte[] noise = new byte[random.nextInt(200)];
            random.nextBytes(noise);
            try {
                var reader = new CommandReader(new ByteArrayInputStream(noise), CLOCK);
                while (reader.read() != null) {
                    // skipped or valid frames are fine
                }
            } catch (ProtocolException expected) {
                // fine
            } catch (Exception e) {
                throw new AssertionError("command reader let " + e + " escape", e);
            }
            try {
                var reader = new SensorDataReader(new ByteArrayInputStream(noise), SensorInfoFilter.Limits.DEFAULT);
                while (reader.read() != null) {
                    // keep reading
                }
            } catch (ProtocolException expected) {
                // fine
            } catch (Exception e) {
                throw new AssertionError("sensor data reader let " + e + " escape", e);
            }
        }
    }

    @Test
    void garbageInsideAValidObjectStreamIsAProtocolError() throws IOException {
        var bytes = new ByteArrayOutputStream();
        var writer = new SensorDataWriter(bytes, 100);
        writer.writeStep(new Uplink.Batch(0, 0, 0, everyShape()), new Uplink.StepMarker(0, 0, false));
        byte[] valid = bytes.toByteArray();
        Random random = new Random(11);
        for (int i = 0; i < 200; i++) {
            byte[] corrupt = valid.clone();
            for (int k = 0; k < 3; k++) {
                int at = 4 + random.nextInt(corrupt.length - 4);
                corrupt[at] = (byte) random.nextInt(256);
            }
            try {
                var reader = new SensorDataReader(new ByteArrayInputStream(corrupt), SensorInfoFilter.Limits.DEFAULT);
                while (reader.read() != null) {
                    // a corrupted value may still parse: that is not the reader's business
                }
            } catch (ProtocolException expected) {
                // fine
            } catch (Exception e) {
                throw new AssertionError("corruption " + i + " let " + e + " escape", e);
            }
        }
        byte[] truncated = Arrays.copyOf(valid, valid.length - 5);
        var e = assertThrows(ProtocolException.class, () -> {
            var reader = new SensorDataReader(new ByteArrayInputStream(truncated), SensorInfoFilter.Limits.DEFAULT);
            while (reader.read() != null) {
                // until the truncation
            }
        });
        assertTrue(e.getMessage().contains("truncated") || e.getMessage().contains("garbage"), e.getMessage());
    }

    @Test
    void handshakeCarriesTheVersionAndRefusesStrangers() throws IOException {
        var bytes = new ByteArrayOutputStream();
        new Protocol.Hello(Protocol.VERSION, "khepera", "navigation", 40, true).write(new DataOutputStream(bytes));
        var hello = Protocol.Hello.read(new DataInputStream(new ByteArrayInputStream(bytes.toByteArray())));
        assertEquals(new Protocol.Hello(Protocol.VERSION, "khepera", "navigation", 40, true), hello);
        assertNull(Protocol.versionMismatch(1, 1));
        assertEquals("protocol version mismatch: the controller speaks version 2, the middleware version 1",
                Protocol.versionMismatch(2, 1));
        var e = assertThrows(ProtocolException.class,
                () -> Protocol.Hello.read(new DataInputStream(new ByteArrayInputStream("GET / HTTP/1.1\r\n".getBytes()))));
        assertTrue(e.getMessage().startsWith("not a jacabot controller"), e.getMessage());
        assertInstanceOf(ProtocolException.class, assertThrows(IOException.class,
                () -> Protocol.Welcome.read(new DataInputStream(new ByteArrayInputStream(new byte[] {0x4A, 0x43})))));
    }
}
