package jacabot.app.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SweepReportTest {
    private static RunOutcome run(String controller, long seed, boolean success, String reason, double contact) {
        var f = new SuccessCriteria.Figures(600, contact, 0.61, 2, 1, 0, false, 1, 1);
        return new RunOutcome(Experiment.SUSPEND_RESUME, "w1", controller, seed, success ? "ok" : "crash", success, reason,
                600, 12.5, f, 412.5, 0);
    }

    @Test
    void csvReadsBackWhatItWrote(@TempDir Path dir) throws Exception {
        List<RunOutcome> runs = List.of(run("agent", 1, true, "", 0.5),
                run("baseline", 2, false, "crash: IllegalStateException: a, \"quoted\" b", 3));
        Path csv = dir.resolve("runs.csv");
        Files.writeString(csv, SweepReport.csv(runs));
        assertEquals(runs, SweepReport.readCsv(csv));
    }

    @Test
    void aBadCsvIsNamedWithItsLine(@TempDir Path dir) throws Exception {
        Path csv = dir.resolve("runs.csv");
        Files.writeString(csv, String.join(",", SweepReport.COLUMNS) + "\nnavigation,w,agent,x\n");
        var e = assertThrows(IllegalArgumentException.class, () -> SweepReport.readCsv(csv));
        assertTrue(e.getMessage().startsWith(csv + ":2: "), e.getMessage());
    }

    @Test
    void theReportCountsSuccessesAndListsFailures() {
        String md = SweepReport.markdown(List.of(run("agent", 1, true, "", 0.5), run("agent", 2, true, "", 1.5),
                run("baseline", 1, false, "crash: boom", 3)), null);
        assertTrue(md.contains("| agent | 2 | 2 (100%) | 1.0 | 61% | 2 | 1 | 0 | 2 of 2 | 0 / 0 / 0 / 0 |"), md);
        assertTrue(md.contains("| baseline | 1 | 0 (0%) | 3.0 |"), md);
        assertTrue(md.contains("- baseline, w1, seed 1: crash: boom"), md);
    }

    @Test
    void mergingDropsRepeatsAndSorts() {
        var a = run("baseline", 1, true, "", 1);
        var b = run("agent", 2, true, "", 1);
        assertEquals(List.of(b, a), SweepReport.merge(List.of(List.of(a), List.of(b, a))));
    }
}
