package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The README's first project, taken from the README itself, runs in an empty folder as shown. */
class ReadmeProjectTest {
    private static final Pattern FILE_BLOCK = Pattern.compile("`([\\w.]+)`:\\n\\n```\\w*\\n(.*?)```", Pattern.DOTALL);
    private static final Pattern SHOWN_RUN = Pattern.compile("```\\n\\$ jacabot run counter.mas2j\\n(.*?)```", Pattern.DOTALL);

    @Test
    void counterInAnEmptyFolderRunsAsTheReadmeShows(@TempDir Path dir) throws Exception {
        String readme = Files.readString(Path.of(System.getProperty("jacabot.projectDir", "."), "README.md"));
        Map<String, String> files = new LinkedHashMap<>();
        Matcher m = FILE_BLOCK.matcher(readme.substring(readme.indexOf("## Your own artifacts")));
        while (m.find() && files.size() < 3) {
            files.put(m.group(1), m.group(2));
        }
        assertEquals(Set.of("Counter.java", "counter.mas2j", "user.asl"), files.keySet());
        Matcher shown = SHOWN_RUN.matcher(readme);
        assertTrue(shown.find(), "the README shows the run");

        ProjectRun.write(dir, files);
        ProjectRun run = ProjectRun.run(dir.resolve("counter.mas2j"), 0, 90_000);
        assertTrue(run.stopped, "the agent stops the run: " + run.output);
        assertEquals(shown.group(1), run.output);
    }
}
