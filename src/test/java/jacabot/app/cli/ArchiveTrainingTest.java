package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The archive's training run splits its arguments into launcher command lines at {@code --then}. */
class ArchiveTrainingTest {

    @Test
    void commandLinesAreSplitAtThen() {
        assertEquals(List.of(List.of("run", "training.mas2j"), List.of("experiment", "navigation", "--headless")),
                ArchiveTraining.commands("run", "training.mas2j", "--then", "experiment", "navigation", "--headless"));
        assertEquals(List.of(List.of("run", "a.mas2j")), ArchiveTraining.commands("--then", "run", "a.mas2j", "--then"));
    }

    @Test
    void theLargestExitCodeIsTheTrainingRunsOwn() {
        // a user error (2) in the second command line is not hidden by the first one's success
        assertEquals(2, ArchiveTraining.run("--version", "--then", "experiment", "no-such-experiment"));
        assertEquals(0, ArchiveTraining.run("--version", "--then", "--version"));
    }
}
