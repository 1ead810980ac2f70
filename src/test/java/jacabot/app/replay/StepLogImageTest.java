package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.sim.SimWorld;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The step log's camera image (format 2): base64 of the pixels' bytes, {@code same} for the
 * image of the step before within a gzip member, whole in every key step; read back as the link
 * carried it. Format 1's decimal text still reads; another format fails with one line.
 */
class StepLogImageTest {
    private static final int STEPS = 2 * StepLog.CHUNK + 30;

    /** A 4x2 image whose pixels change every third step (the robot turning), else stay. */
    private static int[] image(int step) {
        int v = step / 3;
        return new int[] {4, 2, 0xC81E1E, 0xFFFFFF, v & 0xFFFFFF, 0x000000, 0x808080, 0x0A0B0C, 0xFF0000, v * 977 & 0xFFFFFF};
    }

    private static StepLog.Header header() throws Exception {
        SimWorld w = SimWorld.load(SyntheticRun.ROOT.resolve("worlds/navigation.json"));
        return new StepLog.Header(StepLog.FORMAT, "navigation", w.name(), 1, 40, w.robots().get(0).name(), "x.asl",
                w.snapshot(), null);
    }

    @Test
    void everyImageReadsBackAsTheLinkCarriedItAndAnUnchangedOneIsWrittenAsSame(@TempDir Path dir) throws Exception {
        Path file = dir.resolve(StepLog.FILE);
        var body = new StepLog.Body(0, 0, 0, null, 0, 0, null, 0);
        var sunk = new ArrayList<List<String>>();
        try (var log = new StepLog.Writer(file, header(), false).onStep(s -> sunk.add(s.readings()))) {
            for (int i = 0; i < STEPS; i++) {
                var readings = List.of(new SensorInfo(SensorKind.LEFT_DISTANCE.id(), 12.5),
                        SensorInfo.owning(SensorKind.CAMERA_IMAGE.id(), image(i)));
                log.step(40L * (i + 1), body, List.of(), readings, null, null);
            }
        }
        var lines = lines(file);
        int same = 0;
        for (int i = 0; i < STEPS; i++) {
            String line = lines.get(i + 1);
            boolean key = i % StepLog.CHUNK == 0;
            boolean unchanged = i > 0 && Arrays.equals(image(i), image(i - 1));
            assertEquals(!key && unchanged, line.contains("\"" + ImageText.SAME + "\""), "step " + i + ": " + line);
            assertTrue(line.contains("\"LEFT_DISTANCE 12.5\""), line);
            same += line.contains(ImageText.SAME) ? 1 : 0;
        }
        assertTrue(same > STEPS / 2, same + " images written as the one before");
        try (var r = new StepLog.Reader(file)) {
            for (int i = 0; i < STEPS; i++) {
                StepLog.Step s = r.next();
                assertArrayEquals(image(i), ImageText.pixels(s.readings().get(1)), "step " + i);
                assertEquals(s.readings(), sunk.get(i), "the plots' sink sees what a reader reads, step " + i);
            }
            assertEquals(null, r.next());
        }
        // the inspector reads an instant from its member's key step on
        var archive = StepArchive.open(file, (t, x, z) -> {
        });
        assertNotNull(archive.at(40L * (StepLog.CHUNK + 50)));
        var replay = Replay.open(file);
        assertArrayEquals(image(StepLog.CHUNK + 50), ImageText.pixels(replay.frames().get(StepLog.CHUNK + 50).readings().get(1)));
    }

    @Test
    void anImageThatIsNotOfTwentyFourBitColoursIsWrittenAsDecimalText(@TempDir Path dir) throws Exception {
        Path file = dir.resolve(StepLog.FILE);
        int[] odd = {2, 1, -1, 0x1000000};
        try (var log = new StepLog.Writer(file, header(), false)) {
            log.step(40, new StepLog.Body(0, 0, 0, null, 0, 0, null, 0), List.of(),
                    List.of(SensorInfo.owning(SensorKind.CAMERA_IMAGE.id(), odd)), null, null);
        }
        assertTrue(lines(file).get(1).contains("CAMERA_IMAGE [2, 1, -1, 16777216]"), lines(file).get(1));
        try (var r = new StepLog.Reader(file)) {
            assertArrayEquals(odd, ImageText.pixels(r.next().readings().get(0)));
        }
    }

    @Test
    void aFormatOneLogStillReadsAndAnUnknownFormatFailsWithOneLine(@TempDir Path dir) throws Exception {
        Path file = dir.resolve(StepLog.FILE);
        try (var log = new StepLog.Writer(file, header(), false)) {
            log.stepText(40, new StepLog.Body(0, 0, 0, null, 0, 0, null, 0), List.of(), List.of(), null, null);
        }
        String header = lines(file).get(0);
        String step = "{\"t\":40,\"key\":true,\"body\":{\"x\":0.0,\"z\":0.0,\"heading\":0.0,\"left\":0.0,\"right\":0.0,"
                + "\"contactTime\":0.0},\"in\":[\"CAMERA_IMAGE [2, 1, 13115934, 16777215]\"]}";
        Path old = dir.resolve("old.jsonl.gz");
        write(old, header.replace(StepLog.FORMAT, "jacabot-steps/1"), step);
        try (var r = new StepLog.Reader(old)) {
            assertArrayEquals(new int[] {2, 1, 13115934, 16777215}, ImageText.pixels(r.next().readings().get(0)));
        }
        Path future = dir.resolve("future.jsonl.gz");
        write(future, header.replace(StepLog.FORMAT, "jacabot-steps/9"), step);
        var e = assertThrows(IOException.class, () -> new StepLog.Reader(future));
        assertEquals(future + ":1: not a step log this jacabot reads (format 'jacabot-steps/9'; it reads jacabot-steps/1"
                + " and jacabot-steps/2)", e.getMessage());
        // a "same" with no image before it in its member: the line that says so
        Path broken = dir.resolve("broken.jsonl.gz");
        write(broken, header, step.replace("CAMERA_IMAGE [2, 1, 13115934, 16777215]", ImageText.SAME));
        try (var r = new StepLog.Reader(broken)) {
            var b = assertThrows(IOException.class, r::next);
            assertTrue(b.getMessage().startsWith(broken + ":2: "), b.getMessage());
        }
    }

    private static void write(Path file, String... lines) throws IOException {
        try (Writer w = new OutputStreamWriter(new GZIPOutputStream(Files.newOutputStream(file)), StandardCharsets.UTF_8)) {
            for (String l : lines) {
                w.write(l + "\n");
            }
        }
    }

    private static List<String> lines(Path file) throws IOException {
        try (var in = new BufferedReader(new InputStreamReader(new GZIPInputStream(Files.newInputStream(file)),
                StandardCharsets.UTF_8))) {
            return in.lines().toList();
        }
    }
}
