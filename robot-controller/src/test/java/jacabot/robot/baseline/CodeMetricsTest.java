package jacabot.robot.baseline;
import jacabot.robot.Experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

class CodeMetricsTest {
    @Test
    void countsIgnoreCommentsAndLiterals() {
        String src = "/** if (a) { } */\n"
                + "class A {\n"
                + "\n"
                + "    // while (x) { }\n"
                + "    void f(int a, int b) {\n"
                + "        if (a > 0 && b > 0 || a < -1) { print(\"if (no)\"); }\n"
                + "        else if (a == 0) { for (int i = 0; i < 3; i++) { } }\n"
                + "        while (b > 0) { b = a > 1 ? b - 1 : 0; }\n"
                + "    }\n"
                + "}\n";
        CodeMetrics m = CodeMetrics.count(Experiment.OBSTACLE_AVOIDANCE, "A.java", src);
        assertEquals(10, m.lines());
        assertEquals(7, m.codeLines());
        assertEquals(2, m.ifs());
        assertEquals(2, m.loops());
        assertEquals(2 + 2 + 1 + 2, m.conditions());
    }

    @Test
    void eachExperimentsBaselineIsLargerThanThePreviousOnesKhepera() throws IOException {
        Path root = Path.of(System.getProperty("jacabot.rootDir", ".."));
        CodeMetrics one = CodeMetrics.of(Experiment.OBSTACLE_AVOIDANCE, CodeMetrics.sourceDir(root));
        CodeMetrics two = CodeMetrics.of(Experiment.OBJECT_PICKING, CodeMetrics.sourceDir(root));
        CodeMetrics three = CodeMetrics.of(Experiment.NAVIGATION, CodeMetrics.sourceDir(root));
        CodeMetrics four = CodeMetrics.of(Experiment.SUSPEND_RESUME, CodeMetrics.sourceDir(root));
        assertTrue(one.ifs() > 0 && one.loops() > 0, one.toString());
        assertTrue(one.codeLines() < one.lines());
        assertTrue(two.codeLines() < three.codeLines() && three.codeLines() < four.codeLines());
        assertTrue(two.conditions() < three.conditions() && three.conditions() < four.conditions());
        assertEquals(6, four.files().size());
    }

    /** The equal-capability baseline is counted as the thesis-style program plus the routines it calls. */
    @Test
    void theEqualBaselineCountsTheProgramAndItsStrategies() throws Exception {
        Path root = Path.of(System.getProperty("jacabot.rootDir", ".."));
        for (Experiment e : new Experiment[] {Experiment.OBJECT_PICKING, Experiment.NAVIGATION, Experiment.SUSPEND_RESUME}) {
            CodeMetrics thesis = CodeMetrics.of(e, CodeMetrics.sourceDir(root)), equal = CodeMetrics.ofEqual(e, CodeMetrics.sourceDir(root));
            assertTrue(equal.files().containsAll(thesis.files()) && equal.files().contains("EqualCapabilities.java"), e.id());
            assertTrue(equal.codeLines() > thesis.codeLines() + 100 && equal.conditions() > thesis.conditions(), e.id());
        }
        assertEquals(List.of("BaselineController.java", "EqualObstacleAvoidanceBaseline.java"),
                CodeMetrics.ofEqual(Experiment.OBSTACLE_AVOIDANCE, CodeMetrics.sourceDir(root)).files());
    }
}
