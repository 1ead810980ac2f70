package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code jacabot experiment --pipeline}: a pipelined lockstep run writes the same recordings (event
 * log, link log, the agents' console, step log) at every invocation, whatever the timing of its two
 * threads; they differ from the plain lockstep's (a command takes effect a step later); and the
 * option is refused where there is no lockstep in this process to pipeline.
 */
class PipelinedExperimentTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    /** The thesis' agent as published: it prints as it goes, so the console file has lines. */
    private static final String PUBLISHED = ROOT.resolve("agents/src/main/asl/as-published/suspend-resume.asl").toString();

    private static Map<String, String> run(Path out, String... extra) throws IOException {
        var args = new ArrayList<>(List.of("experiment", "suspend-resume", "--headless", "--duration", "30s",
                "--agent", PUBLISHED, "--link-log", "--out", out.toString()));
        args.addAll(List.of(extra));
        String[] r = CliRun.run(args.toArray(String[]::new));
        assertEquals("0", r[0], r[1] + r[2]);
        var files = new LinkedHashMap<String, String>();
        for (String f : new String[] {"event-log.txt", "link-log.txt", "console.txt"}) {
            files.put(f, Files.readString(out.resolve(f)));
        }
        try (var in = new GZIPInputStream(Files.newInputStream(out.resolve("steps.jsonl.gz")))) {
            files.put("steps.jsonl", new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
        return files;
    }

    @Test
    void thePipelinedRecordingsAreTheSameAtEveryRun(@TempDir Path dir) throws Exception {
        Map<String, String> first = run(dir.resolve("a"), "--pipeline");
        Map<String, String> second = run(dir.resolve("b"), "--pipeline");
        assertEquals(first, second);
        assertTrue(first.get("console.txt").contains("[robot]"), "the agent printed");
        assertTrue(first.get("steps.jsonl").lines().count() > 700, "a line per step");
        Map<String, String> plain = run(dir.resolve("p"));
        assertNotEquals(plain.get("link-log.txt"), first.get("link-log.txt"), "a command takes effect a step later");
        assertNotEquals(plain.get("steps.jsonl"), first.get("steps.jsonl"));
    }

    @Test
    void refusedWithoutALockstepToPipeline(@TempDir Path dir) {
        for (String other : new String[] {"--real-time", "--baseline", "--remote-controller"}) {
            String[] r = CliRun.run("experiment", "suspend-resume", "--headless", "--pipeline", other, "--duration", "1s",
                    "--out", dir.toString());
            assertNotEquals("0", r[0], other);
            assertTrue(r[2].contains(other) || r[2].contains("--pipeline"), other + ": " + r[2]);
            assertEquals(1, r[2].strip().lines().count(), "one line: " + r[2]);
        }
    }
}
