package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class SpinningInputTest {
    @Test
    void readsWhatIsThereAtOnce() throws IOException {
        var in = new SpinningInput(new ByteArrayInputStream(new byte[] {1, 2, 3}), TimeUnit.SECONDS.toNanos(5));
        long t0 = System.nanoTime();
        assertEquals(1, in.read());
        byte[] b = new byte[2];
        assertEquals(2, in.read(b, 0, 2));
        assertArrayEquals(new byte[] {2, 3}, b);
        assertTrue(System.nanoTime() - t0 < TimeUnit.SECONDS.toNanos(1), "no spinning while bytes are available");
    }

    @Test
    void blocksAfterItsSpinAndStillGetsTheLaterBytes() throws Exception {
        var source = new PipedInputStream();
        var sink = new PipedOutputStream(source);
        var in = new SpinningInput(source, TimeUnit.MILLISECONDS.toNanos(1));
        Thread writer = new Thread(() -> {
            try {
                Thread.sleep(50); // well past the spin: the read must have blocked meanwhile
                sink.write(42);
                sink.flush();
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        writer.start();
        assertEquals(42, in.read());
        writer.join();
    }

    @Test
    void anEndedStreamEndsTheRead() throws IOException {
        var in = new SpinningInput(new ByteArrayInputStream(new byte[0]), TimeUnit.MILLISECONDS.toNanos(1));
        assertEquals(-1, in.read());
        assertEquals(-1, in.read(new byte[4], 0, 4));
    }

    @Test
    void aNegativeSpinIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new SpinningInput(new ByteArrayInputStream(new byte[0]), -1));
    }
}
