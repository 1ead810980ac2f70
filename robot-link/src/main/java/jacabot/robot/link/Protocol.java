package jacabot.robot.link;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The link protocol between the robot controller (client) and the middleware (server), shared by
 * both sides. One TCP connection, one direction per stream, as in the thesis (§2.3–2.4):
 *
 * <ol>
 *   <li><b>Handshake</b> (plain {@code DataOutputStream}): the controller sends a {@link Hello}
 *       (magic, {@link #VERSION}, robot, world, control step, mode, the sensor ids it will send); the
 *       middleware answers a {@link Welcome}. Different versions never exchange anything else. Then
 *       both prove they hold the shared {@link LinkSecret} ({@link Handshake}).</li>
 *   <li><b>Sensor data</b>, controller → middleware: a Java {@code ObjectOutputStream} carrying
 *       tagged frames ({@link Uplink}); readings are {@link SensorInfo} objects, read back through
 *       {@link SensorInfoFilter}. See {@link SensorDataWriter}/{@link SensorDataReader}.</li>
 *   <li><b>Commands</b>, middleware → controller: fixed-layout frames, an int {@link CommandCode}
 *       then its arguments. See {@link CommandWriter}/{@link CommandReader}.</li>
 * </ol>
 */
public final class Protocol {
    /** "JCBT": the first int of a handshake, so that a stray client is told apart from a controller. */
    public static final int MAGIC = 0x4A434254;
    /** Bumped whenever a frame, a command code or a sensor id changes meaning. */
    public static final int VERSION = 3;
    public static final String DEFAULT_HOST = "127.0.0.1";
    public static final int DEFAULT_PORT = 4444;
    /** The most arguments a command frame may announce; more means the stream is garbage. */
    public static final int MAX_ARGS = 8;
    /** The most readings one batch may announce (a robot has a few dozen devices at most). */
    public static final int MAX_READINGS_PER_BATCH = 64;
    /** The most sensor ids a greeting may declare. */
    public static final int MAX_DECLARED_SENSORS = 64;

    private Protocol() {
    }

    /**
     * The controller's greeting.
     *
     * @param sensors the {@link SensorKind} ids of the devices the robot enabled: the middleware
     *                refuses any other reading ({@link ReadingCheck})
     */
    public record Hello(int version, String robotName, String worldName, int controlStepMs, boolean lockstep,
                        List<Integer> sensors) {
        public Hello {
            sensors = List.copyOf(sensors);
            if (sensors.size() > MAX_DECLARED_SENSORS) {
                throw new IllegalArgumentException("at most " + MAX_DECLARED_SENSORS + " sensors, got " + sensors.size());
            }
        }

        /** A greeting declaring every sensor kind this version knows. */
        public Hello(int version, String robotName, String worldName, int controlStepMs, boolean lockstep) {
            this(version, robotName, worldName, controlStepMs, lockstep,
                    Arrays.stream(SensorKind.values()).map(SensorKind::id).collect(Collectors.toList()));
        }

        public void write(DataOutputStream out) throws IOException {
            out.write(bytes());
            out.flush();
        }

        /** {@return the greeting as on the wire (also what the handshake's proofs cover)} */
        public byte[] bytes() {
            var buffer = new ByteArrayOutputStream();
            try (var out = new DataOutputStream(buffer)) {
                out.writeInt(MAGIC);
                out.writeInt(version);
                out.writeUTF(robotName);
                out.writeUTF(worldName);
                out.writeInt(controlStepMs);
                out.writeBoolean(lockstep);
                out.writeShort(sensors.size());
                for (int id : sensors) {
                    out.writeInt(id);
                }
            } catch (IOException e) {
                throw new IllegalStateException("a byte array cannot fail", e);
            }
            return buffer.toByteArray();
        }

        /** @throws ProtocolException when the peer is not a jacabot controller */
        public static Hello read(DataInputStream in) throws IOException {
            int version = readHeader(in, "controller");
            try {
                String robot = in.readUTF(), world = in.readUTF();
                int step = in.readInt();
                boolean lockstep = in.readBoolean();
                if (version != VERSION) {
                    return new Hello(version, robot, world, step, lockstep, List.of()); // refused anyway
                }
                int n = in.readUnsignedShort();
                if (n > MAX_DECLARED_SENSORS) {
                    throw new ProtocolException("garbage in the handshake: " + n + " sensors declared");
                }
                List<Integer> ids = new ArrayList<>(n);
                for (int i = 0; i < n; i++) {
                    ids.add(in.readInt());
                }
                return new Hello(version, robot, world, step, lockstep, ids);
            } catch (EOFException e) {
                throw new ProtocolException("truncated handshake from the controller");
            }
        }
    }

    /** The middleware's answer: accepted, or refused with a reason (e.g. a version mismatch). */
    public record Welcome(int version, boolean accepted, String message) {
        public void write(DataOutputStream out) throws IOException {
            writeUnflushed(out);
            out.flush();
        }

        void writeUnflushed(DataOutputStream out) throws IOException {
            out.writeInt(MAGIC);
            out.writeInt(version);
            out.writeBoolean(accepted);
            out.writeUTF(message);
        }

        /** @throws ProtocolException when the peer is not a jacabot middleware */
        public static Welcome read(DataInputStream in) throws IOException {
            int version = readHeader(in, "middleware");
            try {
                return new Welcome(version, in.readBoolean(), in.readUTF());
            } catch (EOFException e) {
                throw new ProtocolException("truncated handshake from the middleware");
            }
        }
    }

    /** {@return the refusal message when two versions differ, or null when they agree} */
    public static String versionMismatch(int controllerVersion, int middlewareVersion) {
        if (controllerVersion == middlewareVersion) {
            return null;
        }
        return "protocol version mismatch: the controller speaks version " + controllerVersion
                + ", the middleware version " + middlewareVersion;
    }

    private static int readHeader(DataInputStream in, String peer) throws IOException {
        int magic;
        try {
            magic = in.readInt();
        } catch (EOFException e) {
            throw new ProtocolException("the " + peer + " closed the connection during the handshake");
        }
        if (magic != MAGIC) {
            throw new ProtocolException(String.format("not a jacabot %s: expected magic 0x%08X, got 0x%08X", peer, MAGIC, magic));
        }
        try {
            return in.readInt();
        } catch (EOFException e) {
            throw new ProtocolException("truncated handshake from the " + peer);
        }
    }
}
