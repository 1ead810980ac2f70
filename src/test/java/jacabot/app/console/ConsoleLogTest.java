package jacabot.app.console;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class ConsoleLogTest {
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private ConsoleLog log(Verbosity v) {
        return new ConsoleLog(new PrintWriter(out), new PrintWriter(err), v);
    }

    private static void story(ConsoleLog log) {
        log.info("Experiment 4 (suspend-resume)");
        for (int i = 0; i < 5; i++) {
            log.agents().println("[robot] high left");
        }
        log.info("  t=  10.0 s");
        log.agents().println("[robot] RECHARGED");
        log.detail("[link] connection closed");
        log.warn("w.json is a world of experiment 3");
        log.result("run: suspend-resume");
        log.flush();
    }

    @Test
    void theDefaultFoldsTheAgentsRepeatsAndHidesDetails() {
        story(log(Verbosity.NORMAL));
        assertEquals(String.join(System.lineSeparator(), "Experiment 4 (suspend-resume)", "[robot] high left",
                "[robot] high left (x4 more)", "  t=  10.0 s", "[robot] RECHARGED", "run: suspend-resume", ""), out.toString(),
                "the count comes before the progress line that ends the burst");
        assertEquals("warning: w.json is a world of experiment 3" + System.lineSeparator(), err.toString());
    }

    @Test
    void verbosePrintsEveryLineAsItCame() {
        story(log(Verbosity.VERBOSE));
        assertEquals(5, out.toString().lines().filter(l -> l.equals("[robot] high left")).count(), out.toString());
        assertFalse(out.toString().contains("more)"));
        assertTrue(out.toString().contains("[link] connection closed"));
    }

    @Test
    void quietKeepsOnlyResultsAndWarnings() {
        story(log(Verbosity.QUIET));
        assertEquals("run: suspend-resume" + System.lineSeparator(), out.toString());
        assertTrue(err.toString().contains("warning: w.json"));
    }

    @Test
    void aLineRedrawnInPlaceIsEndedBeforeTheNextLine() {
        var log = log(Verbosity.NORMAL);
        log.inPlace("[#...] 1/3 runs");
        log.inPlace("[##..] 2/3 runs");
        log.warn("cannot write the logs");
        assertEquals("\r[#...] 1/3 runs\r[##..] 2/3 runs" + System.lineSeparator() + "warning: cannot write the logs"
                + System.lineSeparator(), err.toString());
        var quietErr = new StringWriter();
        var quiet = new ConsoleLog(new PrintWriter(out), new PrintWriter(quietErr), Verbosity.QUIET);
        quiet.inPlace("[#...] 1/3 runs");
        assertEquals("", quietErr.toString(), "no progress bar with --quiet");
    }

    @Test
    void bothFlagsAreRefused() {
        assertEquals(Verbosity.QUIET, Verbosity.of(true, false));
        assertEquals(Verbosity.NORMAL, Verbosity.of(false, false));
        try {
            Verbosity.of(true, true);
            throw new AssertionError("accepted --quiet --verbose");
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage().contains("exclude each other"));
        }
    }

    @Test
    void aLineStreamHandsOverWholeLinesHoweverTheyAreWritten() {
        var got = new ArrayList<String>();
        var stream = ConsoleLog.lines(got::add);
        stream.print("[a] par");
        stream.print("tial ");
        stream.println("line");
        stream.println("two\nlines in one");
        stream.print("windows\r\n");
        stream.println("café ✓");
        stream.write('x');
        stream.write('\n');
        stream.print("unfinished");
        assertEquals(List.of("[a] partial line", "two", "lines in one", "windows", "café ✓", "x"), got);
    }
}
