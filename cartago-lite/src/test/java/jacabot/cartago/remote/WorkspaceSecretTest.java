package jacabot.cartago.remote;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The workspace secret file: made whole, for its owner only, and the same for processes that make it at once. */
class WorkspaceSecretTest {
    private static final byte[] PROBE = "probe".getBytes(StandardCharsets.US_ASCII);

    /** Four makers at once, 40 times: each side ends with the file's secret, none reads a half-made file. */
    @Test
    void makersStartingTogetherEndWithTheSameSecret(@TempDir Path dir) throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            for (int round = 0; round < 40; round++) {
                Path file = dir.resolve("round-" + round).resolve("workspace-secret");
                var start = new CountDownLatch(1);
                List<Future<WorkspaceSecret>> sides = new ArrayList<>();
                for (int side = 0; side < 4; side++) {
                    sides.add(pool.submit(() -> {
                        start.await();
                        return WorkspaceSecret.loadOrCreate(file);
                    }));
                }
                start.countDown();
                byte[] first = sides.get(0).get(10, TimeUnit.SECONDS).mac(PROBE); // a half-made file would throw
                byte[] expected = WorkspaceSecret.loadOrCreate(file).mac(PROBE); // the file's, read back
                assertArrayEquals(expected, first);
                for (var side : sides) {
                    assertArrayEquals(expected, side.get(10, TimeUnit.SECONDS).mac(PROBE), "round " + round + ": the file's secret");
                }
                assertEquals(PosixFilePermissions.fromString("rw-------"), Files.getPosixFilePermissions(file));
                try (var left = Files.list(file.getParent())) {
                    assertEquals(List.of(file), left.toList(), "no temporary file left beside it");
                }
            }
        } finally {
            pool.shutdownNow();
        }
    }
}
