package jacabot.robot.link;

import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.List;

/**
 * Writes command frames: {@code int code, int seq, long sentMicros, int argc, double × argc}. The
 * thesis wrote {@code out.writeInt(SET_SPEED); out.writeDouble(x); out.writeDouble(y)}; the
 * sequence number and send time let the controller report when each command took effect, and the
 * argument count lets a reader skip a code it does not know without losing the stream.
 */
public final class CommandWriter {
    private final DataOutputStream out;
    /** Frames written so far: an in-process reader reads as many ({@link MemoryLink}). */
    private long framesWritten;

    public CommandWriter(OutputStream out) {
        this.out = new DataOutputStream(out);
    }

    /** Writes and flushes one command. Thread-safe: frames are never interleaved. */
    public synchronized void write(int seq, long sentMicros, Command command) throws IOException {
        writeFrame(seq, sentMicros, command);
        out.flush();
        framesWritten++;
    }

    /** Writes {@code commands.get(i)} with sequence number {@code seqs[i]}, then flushes once. */
    public synchronized void writeAll(int[] seqs, long sentMicros, List<Command> commands) throws IOException {
        for (int i = 0; i < commands.size(); i++) {
            writeFrame(seqs[i], sentMicros, commands.get(i));
        }
        out.flush();
        framesWritten += commands.size();
    }

    /** {@return the frames written and flushed so far} */
    public synchronized long framesWritten() {
        return framesWritten;
    }

    private void writeFrame(int seq, long sentMicros, Command command) throws IOException {
        double[] args = command.args();
        out.writeInt(command.code().code());
        out.writeInt(seq);
        out.writeLong(sentMicros);
        out.writeInt(args.length);
        for (double a : args) {
            out.writeDouble(a);
        }
    }
}
