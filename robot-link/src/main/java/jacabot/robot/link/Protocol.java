package jacabot.robot.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;

/**
 * The link protocol between the robot controller (client) and the middleware (server), shared by
 * both sides. One TCP connection, one direction per stream, as in the thesis (§2.3–2.4):
 *
 * <ol>
 *   <li><b>Handshake</b> (plain {@code DataOutputStream}): the controller sends a {@link Hello}
 *       (magic, {@link #VERSION}, robot, world, control step, mode); the middleware answers a
 *       {@link Welcome}. Different versions never exchange anything else.</li>
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
    public static final int VERSION = 1;
    public static final String DEFAULT_HOST = "127.0.0.1";
    public static final int DEFAULT_PORT = 4444;
    /** The most arguments a command frame may announce; more means the stream is garbage. */
    public static final int MAX_ARGS = 8;
    /** The most readings one batch may announce. */
    public static final int MAX_READINGS_PER_BATCH = 1024;

    private Protocol() {
    }

    /** The controller's greeting. */
    public record Hello(int version, String robotName, String worldName, int controlStepMs, boolean lockstep) {
        public void write(DataOutputStream out) throws IOException {
            out.writeInt(MAGIC);
            out.writeInt(version);
            out.writeUTF(robotName);
            out.writeUTF(worldName);
            out.writeInt(controlStepMs);
            out.writeBoolean(lockstep);
            out.flush();
        }

        /** @throws ProtocolException when the peer is not a jacabot controller */
        public static Hello read(DataInputStream in) throws IOException {
            int version = readHeader(in, "controller");
            try {
                return new Hello(version, in.readUTF(), in.readUTF(), in.readInt(), in.readBoolean());
            } catch (EOFException e) {
                throw new ProtocolException("truncated handshake from the controller");
            }
        }
    }

    /** The middleware's answer: accepted, or refused with a reason (e.g. a version mismatch). */
    public record Welcome(int version, boolean accepted, String message) {
        public void write(DataOutputStream out) throws IOException {
            out.writeInt(MAGIC);
            out.writeInt(version);
            out.writeBoolean(accepted);
            out.writeUTF(message);
            out.flush();
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
