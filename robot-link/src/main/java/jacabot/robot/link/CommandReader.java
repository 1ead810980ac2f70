package jacabot.robot.link;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;

/** Reads the frames {@link CommandWriter} writes, refusing garbage instead of trusting it. */
public final class CommandReader {
    private final DataInputStream in;
    private final LinkClock clock;

    public CommandReader(InputStream in, LinkClock clock) {
        this.in = new DataInputStream(new BufferedInputStream(in));
        this.clock = clock;
    }

    /** {@return whether a frame's first byte can be read without blocking} */
    public boolean ready() throws IOException {
        return in.available() > 0;
    }

    /**
     * Reads the next frame, blocking.
     *
     * @return the command, or a skipped frame with its reason; null when the middleware closed the
     *     connection between two frames
     * @throws ProtocolException for a truncated frame or an impossible argument count (garbage: the
     *     stream cannot be resynchronised, close the connection)
     */
    public ReceivedCommand read() throws IOException {
        int first = in.read();
        if (first < 0) {
            return null;
        }
        int code, seq, argc;
        long sent;
        double[] args;
        try {
            code = (first << 24) | (in.readUnsignedByte() << 16) | (in.readUnsignedByte() << 8) | in.readUnsignedByte();
            seq = in.readInt();
            sent = in.readLong();
            argc = in.readInt();
            if (argc < 0 || argc > Protocol.MAX_ARGS) {
                throw new ProtocolException("garbage on the command stream: code " + code + " announces " + argc
                        + " arguments (at most " + Protocol.MAX_ARGS + ")");
            }
            args = new double[argc];
            for (int i = 0; i < argc; i++) {
                args[i] = in.readDouble();
            }
        } catch (EOFException e) {
            throw new ProtocolException("truncated command frame: the connection ended inside a frame");
        }
        long received = clock.nowMicros();
        var known = CommandCode.of(code);
        if (known.isEmpty()) {
            return new ReceivedCommand(seq, sent, received, null, "unknown command code " + code);
        }
        try {
            return new ReceivedCommand(seq, sent, received, Command.of(known.get(), args), null);
        } catch (IllegalArgumentException e) {
            return new ReceivedCommand(seq, sent, received, null,
                    e.getMessage() + " (code " + code + ", args " + Arrays.toString(args) + ")");
        }
    }
}
