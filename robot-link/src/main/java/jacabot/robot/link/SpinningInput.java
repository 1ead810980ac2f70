package jacabot.robot.link;

import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;

/**
 * A socket's input that polls for a while before a read blocks: for lockstep, where each side
 * answers the other within tens of microseconds. A thread blocked in {@code read} is parked, and the
 * writer pays for waking it; on a virtual machine whose other vCPU has gone idle that costs as much
 * as the step's work. Polling yields at each turn, so a thread with work to do on the same core runs
 * first. Only for plain sockets: a TLS socket's {@code available()} counts decrypted bytes only.
 */
public final class SpinningInput extends FilterInputStream {
    /** Longer than either side's usual turn in lockstep (50–100 µs), short against a slow agent's. */
    public static final long LOCKSTEP_SPIN_NANOS = 200_000;

    private final long spinNanos;

    /** @param spinNanos how long to poll before a read blocks; 0: never */
    public SpinningInput(InputStream in, long spinNanos) {
        super(in);
        if (spinNanos < 0) {
            throw new IllegalArgumentException("spin time must be >= 0: " + spinNanos);
        }
        this.spinNanos = spinNanos;
    }

    @Override
    public int read() throws IOException {
        spin();
        return super.read();
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        spin();
        return super.read(b, off, len);
    }

    private void spin() throws IOException {
        if (spinNanos == 0 || in.available() > 0) {
            return;
        }
        long end = System.nanoTime() + spinNanos;
        while (in.available() == 0 && System.nanoTime() - end < 0) {
            Thread.yield();
        }
    }
}
