package jacabot.app.bench;

import jacabot.experiments.link.LatencyRecorder;
import jacabot.experiments.link.LatencyStats;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * What one hand-off costs on this machine, the floor under the reactive and response times: a
 * parked thread woken by another, and one byte written to a loopback TCP socket whose reader is
 * blocked; each sample after a millisecond of idleness, as between two control steps. Both need
 * the operating system to schedule the sleeping thread again.
 */
final class WakeUpFloor {
    private static final long GAP_NANOS = 1_000_000;

    private WakeUpFloor() {
    }

    /** {@return the delays from unpark to the parked thread running, in microseconds} */
    static LatencyStats threadWakeUps(int samples) throws InterruptedException {
        LatencyRecorder recorder = new LatencyRecorder(samples);
        AtomicLong sent = new AtomicLong();
        Semaphore done = new Semaphore(0);
        Thread sleeper = new Thread(() -> {
            for (int i = 0; i < samples; i++) {
                long t;
                while ((t = sent.getAndSet(0)) == 0) {
                    LockSupport.park();
                }
                recorder.record((System.nanoTime() - t) / 1000);
                done.release();
            }
        }, "wake-up-floor");
        sleeper.setDaemon(true);
        sleeper.start();
        for (int i = 0; i < samples; i++) {
            LockSupport.parkNanos(GAP_NANOS);
            sent.set(System.nanoTime());
            LockSupport.unpark(sleeper);
            if (!done.tryAcquire(1, TimeUnit.SECONDS)) {
                break;
            }
        }
        return recorder.stats();
    }

    /** {@return the delays from writing a byte to the blocked reader having it, in microseconds} */
    static LatencyStats socketWakeUps(int samples) throws IOException, InterruptedException {
        LatencyRecorder recorder = new LatencyRecorder(samples);
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
             Socket writer = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort());
             Socket reader = server.accept()) {
            writer.setTcpNoDelay(true);
            OutputStream out = writer.getOutputStream();
            InputStream in = reader.getInputStream();
            AtomicLong sent = new AtomicLong();
            Semaphore done = new Semaphore(0);
            Thread receiving = new Thread(() -> {
                try {
                    for (int i = 0; i < samples && in.read() >= 0; i++) {
                        recorder.record((System.nanoTime() - sent.get()) / 1000);
                        done.release();
                    }
                } catch (IOException e) {
                    // closed
                }
            }, "socket-floor");
            receiving.setDaemon(true);
            receiving.start();
            for (int i = 0; i < samples; i++) {
                LockSupport.parkNanos(GAP_NANOS);
                sent.set(System.nanoTime());
                out.write(1);
                out.flush();
                if (!done.tryAcquire(1, TimeUnit.SECONDS)) {
                    break;
                }
            }
        }
        return recorder.stats();
    }
}
