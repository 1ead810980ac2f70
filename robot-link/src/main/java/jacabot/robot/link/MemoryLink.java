package jacabot.robot.link;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;

/**
 * The link between a controller and a middleware of one JVM without a socket (sweeps).
 * The frames and their codecs stay the protocol's: the controller writes its sensor data stream
 * with {@link SensorDataWriter} and the middleware reads it back with {@link SensorDataReader} and
 * its filter; commands go through {@link CommandWriter} and {@link CommandReader}. Only the bytes'
 * way differs: one in-memory pipe per direction, and the reading end reads a write's whole frames
 * at once, on the writing thread. A lockstep step is then one call chain on the simulation thread
 * (readings, middleware, agent, commands, controller): no system call and no thread hand-off.
 *
 * <p>No handshake: no port is open, and only code holding this object reaches either end, so there
 * is nobody to authenticate. One connection: once either end closes it, it stays closed.
 *
 * <p>A write and the other end's reading of it hold one monitor, {@code lock}: the controller's
 * world, which its simulation thread holds through a control step. So a command written from any
 * thread takes the same single lock as a step in progress, and two locks are never taken in two orders.
 *
 * <pre>{@code
 * MemoryLink link = new MemoryLink(world);
 * link.listen(hello -> frames -> ...);           // the middleware: reads `frames` frames of link.middlewareIn()
 * var out = new SensorDataWriter(link.controllerOut(), 100);
 * link.connect(hello, out, commands -> ...);     // the controller: reads `commands` frames of link.controllerIn()
 * link.fromController(w -> w.writeStep(batch, marker)); // the middleware has read both frames on return
 * }</pre>
 */
public final class MemoryLink {
    /** One end's reading side, called on the other end's writing thread; it handles its own failures. */
    public interface Reader {
        /** Reads the {@code frames} whole frames the other end has just written. */
        void read(long frames);

        /** The link is closed (by either end); called once. */
        void closed(String reason);
    }

    /** The middleware's side: given the controller's greeting, {@return the reader of its sensor data stream} */
    @FunctionalInterface
    public interface Acceptor {
        Reader accept(Protocol.Hello hello) throws IOException;
    }

    /** A write through one end's writer. */
    @FunctionalInterface
    public interface Write<W> {
        void to(W writer) throws IOException;
    }

    private final Object lock;
    private final Pipe up = new Pipe(), down = new Pipe();
    private final CommandWriter commands = new CommandWriter(down.out);
    private Acceptor acceptor;
    private SensorDataWriter sensorData;
    private volatile Reader middleware, controller;
    private long upFramesRead, downFramesRead;
    private volatile String closedReason;

    /** @param lock the monitor of every write and its reading (the controller's world) */
    public MemoryLink(Object lock) {
        this.lock = lock;
    }

    /** The middleware end: {@code acceptor} meets the controller when it connects. */
    public void listen(Acceptor a) {
        synchronized (lock) {
            if (acceptor != null) {
                throw new IllegalStateException("the in-process link has a middleware already");
            }
            acceptor = a;
        }
    }

    /** {@return where the controller's {@link SensorDataWriter} writes} */
    public OutputStream controllerOut() {
        return up.out;
    }

    /** {@return where the controller's {@link CommandReader} reads} */
    public InputStream controllerIn() {
        return down.in;
    }

    /** {@return where the middleware's {@link SensorDataReader} reads (its stream header first)} */
    public InputStream middlewareIn() {
        return up.in;
    }

    /**
     * The controller end connects: {@code out} (over {@link #controllerOut()}, its header written)
     * carries its frames from now on, and {@code reader} reads the middleware's commands.
     *
     * @throws IOException when nobody listens, the link is closed, or the middleware refuses
     */
    public void connect(Protocol.Hello hello, SensorDataWriter out, Reader reader) throws IOException {
        synchronized (lock) {
            if (acceptor == null) {
                throw new IOException("no middleware listens on this in-process link");
            }
            if (sensorData != null || closedReason != null) {
                throw new IOException("the in-process link is " + (closedReason != null ? "closed" : "taken")
                        + " (one connection only)");
            }
            upFramesRead = out.framesFlushed();
            middleware = acceptor.accept(hello);
            sensorData = out;
            controller = reader;
        }
    }

    /**
     * The controller writes; once its frames are flushed the middleware reads them, before this
     * returns. Frames written unflushed wait for the next write that flushes, as on a socket.
     */
    public void fromController(Write<SensorDataWriter> write) throws IOException {
        synchronized (lock) {
            if (closedReason != null || sensorData == null) {
                throw notOpen();
            }
            write.to(sensorData);
            long flushed = sensorData.framesFlushed();
            long n = flushed - upFramesRead;
            upFramesRead = flushed;
            if (n > 0) {
                middleware.read(n);
            }
        }
    }

    /** The middleware writes commands; the controller has read them when this returns. */
    public void fromMiddleware(Write<CommandWriter> write) throws IOException {
        synchronized (lock) {
            if (closedReason != null || controller == null) {
                throw notOpen();
            }
            write.to(commands);
            long written = commands.framesWritten();
            long n = written - downFramesRead;
            downFramesRead = written;
            if (n > 0) {
                controller.read(n);
            }
        }
    }

    private IOException notOpen() {
        return new IOException("the in-process link is " + (closedReason != null ? "closed: " + closedReason : "not connected"));
    }

    public boolean isClosed() {
        return closedReason != null;
    }

    /**
     * Closes the link: both ends hear {@code reason}, the middleware first. From another thread than
     * a write's, they hear it without the lock held: a close never waits for a step in progress.
     */
    public void close(String reason) {
        Reader m, c;
        synchronized (this) {
            if (closedReason != null) {
                return;
            }
            closedReason = reason;
            m = middleware;
            c = controller;
        }
        if (m != null) {
            m.closed(reason);
        }
        if (c != null) {
            c.closed(reason);
        }
    }

    /**
     * Bytes written by one end and read by the other. The readers only ask for frames that were
     * written whole, so an empty pipe asked for a byte means the two ends disagree: an error, not a wait.
     */
    private static final class Pipe {
        private byte[] buf = new byte[8192];
        private int readPos, writePos;

        final OutputStream out = new OutputStream() {
            @Override
            public void write(int b) {
                ensure(1);
                buf[writePos++] = (byte) b;
            }

            @Override
            public void write(byte[] b, int off, int len) {
                ensure(len);
                System.arraycopy(b, off, buf, writePos, len);
                writePos += len;
            }
        };

        final InputStream in = new InputStream() {
            @Override
            public int read() throws IOException {
                if (readPos == writePos) {
                    throw nothing();
                }
                return buf[readPos++] & 0xff;
            }

            @Override
            public int read(byte[] b, int off, int len) throws IOException {
                if (len == 0) {
                    return 0;
                }
                int n = Math.min(len, writePos - readPos);
                if (n == 0) {
                    throw nothing();
                }
                System.arraycopy(buf, readPos, b, off, n);
                readPos += n;
                return n;
            }

            @Override
            public int available() {
                return writePos - readPos;
            }
        };

        /** Room for {@code n} more bytes: the unread bytes move to the front, the buffer grows if still short. */
        private void ensure(int n) {
            if (writePos + n <= buf.length) {
                return;
            }
            int unread = writePos - readPos;
            byte[] target = unread + n <= buf.length ? buf : new byte[Math.max(buf.length * 2, unread + n)];
            System.arraycopy(buf, readPos, target, 0, unread);
            buf = target;
            readPos = 0;
            writePos = unread;
        }

        private static IOException nothing() {
            return new IOException("in-process link: a frame was read that was never written whole");
        }
    }
}
