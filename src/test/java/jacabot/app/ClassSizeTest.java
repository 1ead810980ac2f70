package jacabot.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The project's rule for readable code: no main class over 600 lines, in any module. */
class ClassSizeTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", ".")).toAbsolutePath().normalize();
    static final int MAX_LINES = 600;

    @Test
    void noMainSourceFileIsOverTheLimit() throws IOException {
        List<Path> sources;
        try (Stream<Path> files = Files.walk(ROOT)) {
            sources = files.filter(p -> p.toString().endsWith(".java"))
                    .filter(p -> ROOT.relativize(p).toString().matches("([\\w-]+/)?src/(main|bridge)/.*"))
                    .toList();
        }
        assertTrue(sources.size() > 100, "the modules' main sources are found under " + ROOT + ": " + sources.size());
        List<String> over = sources.stream().filter(p -> lines(p) > MAX_LINES)
                .map(p -> ROOT.relativize(p) + " has " + lines(p) + " lines").toList();
        assertEquals(List.of(), over);
    }

    private static long lines(Path p) {
        try (Stream<String> s = Files.lines(p)) {
            return s.count();
        } catch (IOException e) {
            throw new IllegalStateException(p + ": " + e.getMessage(), e);
        }
    }
}
