package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The console file read by time: ranges and windows across many index blocks, a file still growing, the event log as fallback. */
class ConsoleFileTest {
    /** Line i at 40 ms * (i / 3): three lines per control step, as an agent printing several lines in one step. */
    private static String line(int i) {
        return String.format(Locale.ROOT, "t=%.3f [robot] line %d", 0.040 * (i / 3), i);
    }

    private static long time(int i) {
        return 40L * (i / 3);
    }

    @Test
    void rangesAndWindowsOverManyBlocksOfAGrowingFile(@TempDir Path dir) throws Exception {
        Path f = dir.resolve(ConsoleFile.FILE);
        var text = new StringBuilder();
        for (int i = 0; i < 1000; i++) {
            text.append(line(i)).append('\n');
        }
        Files.writeString(f, text + "t=13.360 [robot] half a li", StandardCharsets.UTF_8); // the last line is being written
        ConsoleFile c = ConsoleFile.of(dir);

        // a stretch of time: every line in it, with its time, and nothing else (index blocks of 128 lines cross it)
        List<ConsoleFile.Line> got = c.between(5_000, 9_000, 1000);
        var expected = new ArrayList<ConsoleFile.Line>();
        for (int i = 0; i < 1000; i++) {
            if (time(i) >= 5_000 && time(i) <= 9_000) {
                expected.add(new ConsoleFile.Line(time(i), "[robot] line " + i));
            }
        }
        assertEquals(expected, got);
        assertEquals(expected.subList(0, 10), c.between(5_000, 9_000, 10), "at most max lines, the first ones");
        assertEquals(List.of(new ConsoleFile.Line(13_320, "[robot] line 999")), c.between(13_320, 99_000, 10),
                "a line still being written is not read");
        assertEquals(3, c.between(0, 0, 10).size());

        // a window around an instant: the last lines at or before it, the first after it
        ConsoleFile.Window w = c.around(8_000, 200, 4);
        assertEquals(204, w.lines().size());
        assertEquals(new ConsoleFile.Line(8_000, "[robot] line 602"), w.lines().get(199), "the last line at the instant");
        assertEquals(new ConsoleFile.Line(8_040, "[robot] line 603"), w.lines().get(200));
        assertEquals("[robot] line 403", w.lines().get(0).text());
        assertTrue(w.earlier() && w.later());
        ConsoleFile.Window start = c.around(0, 40, 2);
        assertEquals(5, start.lines().size());
        assertFalse(start.earlier(), "nothing before the run's first line");

        // the file grows (a live run): the next query reads the new lines too
        Files.writeString(f, "ne\nt=13.400 [robot] next\n", StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        assertEquals(List.of(new ConsoleFile.Line(13_360, "[robot] half a line"), new ConsoleFile.Line(13_400, "[robot] next")),
                c.between(13_360, 99_000, 10));
        ConsoleFile.Window end = c.around(99_000, 2, 5);
        assertEquals(2, end.lines().size());
        assertFalse(end.later());

        // the inspector's queries
        var answer = c.answer(Map.of("from", "5000", "to", "9000", "text", "line 42"));
        assertEquals(List.of(new ConsoleFile.Line(5_600, "[robot] line 420"), new ConsoleFile.Line(5_600, "[robot] line 421"),
                new ConsoleFile.Line(5_600, "[robot] line 422"), new ConsoleFile.Line(5_640, "[robot] line 423"),
                new ConsoleFile.Line(5_640, "[robot] line 424"), new ConsoleFile.Line(5_640, "[robot] line 425"),
                new ConsoleFile.Line(5_680, "[robot] line 426"), new ConsoleFile.Line(5_680, "[robot] line 427"),
                new ConsoleFile.Line(5_680, "[robot] line 428"), new ConsoleFile.Line(5_720, "[robot] line 429")), answer.get("lines"));
        assertThrows(IllegalArgumentException.class, () -> c.answer(Map.of("before", "3")), "neither an instant nor a stretch");
        assertThrows(IllegalArgumentException.class, () -> c.answer(Map.of("t", "soon")));
    }

    @Test
    void aRunWithoutAConsoleFileShowsItsEventLog(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve(ConsoleFile.EVENT_LOG), "t=16.224 world: robot 'khepera' grasped 'red1'\nt=16.240 picked cylinder red1\n");
        ConsoleFile c = ConsoleFile.of(dir);
        assertEquals(ConsoleFile.EVENT_LOG, c.file().getFileName().toString());
        assertEquals(List.of(new ConsoleFile.Line(16_224, "world: robot 'khepera' grasped 'red1'"),
                new ConsoleFile.Line(16_240, "picked cylinder red1")), c.between(0, Long.MAX_VALUE, 10));
        assertEquals(List.of(), ConsoleFile.of(dir.resolve("nothing-there")).between(0, Long.MAX_VALUE, 10), "no file: no line");
    }
}
