package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.Writer;
import java.lang.management.ManagementFactory;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A 10-minute run with the inspector keeps a flat heap: {@code jacabot experiment navigation
 * --headless --inspector --duration 10m}, run through the launcher's command line, is stopped at
 * its progress lines (every 10 s of simulated time, printed on the run's own thread, so the run
 * waits) and the live heap is measured after full collections. The heap late in the run must not
 * exceed the heap early in it by more than {@link #MARGIN_MB}: what the plots' columns and the
 * world's trajectory add (about 100 bytes a control step, 1.5 MB over the 8 minutes between the
 * samples) and the bounded memos' filling. A history kept in memory (a frame is kilobytes, 12 000
 * steps between the samples) or a buffer grown by one busy stretch and kept fails it. At the end
 * the page still shows the run's first step, read from the step log.
 */
@Tag("long")
class InspectorHeapTest {
    static final double MARGIN_MB = 4;
    private static final Pattern PROGRESS = Pattern.compile("\\s*t=\\s*(\\d+)\\.0 s .*");
    private static final Pattern ADDRESS = Pattern.compile("Mind inspector: (http://\\S+)");

    @Test
    @Timeout(600)
    void aTenMinuteRunWithTheInspectorKeepsAFlatHeap(@TempDir Path dir) throws Exception {
        var heap = new TreeMap<Integer, Double>();
        var firstStep = new StringBuilder();
        var out = new StringWriter();
        Writer sampler = new Writer() {
            private final StringBuilder line = new StringBuilder();
            private String address;

            @Override
            public void write(char[] buf, int off, int len) {
                for (int i = off; i < off + len; i++) {
                    if (buf[i] == '\n') {
                        seen(line.toString());
                        line.setLength(0);
                    } else {
                        line.append(buf[i]);
                    }
                }
            }

            private void seen(String l) {
                out.write(l + "\n");
                Matcher a = ADDRESS.matcher(l);
                if (a.find()) {
                    address = a.group(1);
                }
                Matcher m = PROGRESS.matcher(l);
                int t = m.matches() ? Integer.parseInt(m.group(1)) : -1;
                if (t > 0 && (t % 60 == 0 || t == 590)) {
                    heap.put(t, liveHeapMb());
                    if (t == 590) {
                        firstStep.append(get(address.replace("/?", "/api/state?agent=robot&t=0&")));
                    }
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        var cl = JacabotCommand.commandLine("experiment");
        cl.setOut(new PrintWriter(sampler, true));
        cl.setErr(new PrintWriter(out, true));
        int code = cl.execute("experiment", "navigation", "--headless", "--inspector", "--duration", "10m",
                "--out", dir.resolve("run").toString());
        assertEquals(0, code, out.toString());

        var figures = new StringBuilder("live heap after GC (MB) at simulated time (s):");
        heap.forEach((t, mb) -> figures.append(String.format(Locale.ROOT, " %d s %.1f;", t, mb)));
        System.out.println(figures);
        assertTrue(heap.keySet().containsAll(List.of(180, 480, 540, 590)), figures.toString());
        // early: once the inspector's rings of recent frames are full (at most 500 frames of 250 ms)
        double early = heap.get(180);
        double late = Math.max(heap.get(480), Math.max(heap.get(540), heap.get(590)));
        assertTrue(late <= early + MARGIN_MB, String.format(Locale.ROOT,
                "the heap grew from %.1f MB early to %.1f MB late, more than %.0f MB: %s", early, late, MARGIN_MB, figures));
        // the history still reaches the first step: from the step log on disk, not from memory
        Map<?, ?> state = new ObjectMapper().readValue(firstStep.toString(), Map.class);
        assertTrue(((Number) ((Map<?, ?>) state.get("mind")).get("timeMs")).longValue() <= 40, firstStep.toString());
    }

    /**
     * {@return the live heap in MB}: the least used heap after full collections, repeated while
     * the step log's writer drains its queue (up to 256 captured steps) and the figure still falls.
     */
    private static double liveHeapMb() {
        var memory = ManagementFactory.getMemoryMXBean();
        long least = Long.MAX_VALUE;
        for (int i = 0; i < 12; i++) {
            try {
                Thread.sleep(250);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            System.gc();
            long used = memory.getHeapMemoryUsage().getUsed();
            if (i >= 3 && used > least - 200_000) {
                least = Math.min(least, used);
                break; // no longer falling
            }
            least = Math.min(least, used);
        }
        return least / 1e6;
    }

    private static String get(String url) {
        try {
            var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
            HttpResponse<String> r = client.send(HttpRequest.newBuilder(URI.create(url)).build(), HttpResponse.BodyHandlers.ofString());
            return r.body();
        } catch (Exception e) {
            return "{\"error\":\"" + e + "\"}";
        }
    }
}
