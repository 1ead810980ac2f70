package jacabot.robot.baseline;
import jacabot.robot.Experiment;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Size and decision counts of a baseline's source, for the Chapter 5 comparison ("a lot of tests
 * positioned in a large number of lines", §1): the files a baseline is made of (its own class, the
 * classes it extends, the helpers it calls), counted after removing comments and literals.
 *
 * @param files      the source files counted, by name
 * @param lines      physical lines, comments included
 * @param codeLines  lines with code once comments are removed
 * @param ifs        {@code if} statements ({@code else if} included)
 * @param loops      {@code while} and {@code for} loops (the polling loops)
 * @param conditions every test: ifs, loops, {@code ?:} and each extra {@code &&}/{@code ||} operand
 */
public record CodeMetrics(Experiment experiment, List<String> files, int lines, int codeLines, int ifs, int loops,
                          int conditions) {
    private static final Pattern IF = Pattern.compile("\\bif\\s*\\(");
    private static final Pattern LOOP = Pattern.compile("\\b(while|for)\\s*\\(");
    private static final Pattern TERNARY = Pattern.compile("\\s\\?\\s");
    private static final Pattern CONNECTIVE = Pattern.compile("&&|\\|\\|");
    private static final Pattern COMMENTS_AND_LITERALS = Pattern.compile(
            "/\\*.*?\\*/|//[^\\n]*|\"(?:\\\\.|[^\"\\\\])*\"|'(?:\\\\.|[^'\\\\])*'", Pattern.DOTALL);

    /** Copies the list. */
    public CodeMetrics {
        files = List.copyOf(files);
    }

    /** {@return the source files of an experiment's baseline, in package {@code jacabot.robot.baseline}} */
    public static List<String> sources(Experiment e) {
        switch (e) {
            case OBSTACLE_AVOIDANCE:
                return List.of("BaselineController.java", "RandomMotion.java", "ObstacleAvoidanceBaseline.java");
            case OBJECT_PICKING:
                return List.of("BaselineController.java", "RandomMotion.java", "KheperaIo.java",
                        "ObjectPickingBaseline.java");
            case NAVIGATION:
                return List.of("BaselineController.java", "RandomMotion.java", "KheperaIo.java",
                        "ObjectPickingBaseline.java", "NavigationBaseline.java");
            case SUSPEND_RESUME:
                return List.of("BaselineController.java", "RandomMotion.java", "KheperaIo.java",
                        "ObjectPickingBaseline.java", "NavigationBaseline.java", "SuspendResumeBaseline.java");
            default:
                throw new IllegalArgumentException("no baseline for " + e);
        }
    }

    /**
     * {@return the source files of an experiment's equal-capability baseline}: the thesis-style
     * program and the agents' strategies it calls, or for obstacle avoidance its own program
     */
    public static List<String> equalSources(Experiment e) {
        if (e == Experiment.OBSTACLE_AVOIDANCE) {
            return List.of("BaselineController.java", "EqualObstacleAvoidanceBaseline.java");
        }
        List<String> files = new ArrayList<>(sources(e));
        files.add("EqualCapabilities.java");
        return files;
    }

    /** {@return the baseline package's source directory under the repository root} */
    public static Path sourceDir(Path repositoryRoot) {
        return repositoryRoot.resolve("robot-controller/src/main/java/jacabot/robot/baseline");
    }

    /** {@return the metrics of an experiment's baseline, read from its source directory} */
    public static CodeMetrics of(Experiment e, Path sourceDir) throws IOException {
        return of(e, sources(e), sourceDir);
    }

    /** {@return the metrics of an experiment's equal-capability baseline} */
    public static CodeMetrics ofEqual(Experiment e, Path sourceDir) throws IOException {
        return of(e, equalSources(e), sourceDir);
    }

    private static CodeMetrics of(Experiment e, List<String> sources, Path sourceDir) throws IOException {
        int lines = 0, code = 0, ifs = 0, loops = 0, conditions = 0;
        for (String file : sources) {
            String text = Files.readString(sourceDir.resolve(file), StandardCharsets.UTF_8);
            CodeMetrics m = count(e, file, text);
            lines += m.lines;
            code += m.codeLines;
            ifs += m.ifs;
            loops += m.loops;
            conditions += m.conditions;
        }
        return new CodeMetrics(e, sources, lines, code, ifs, loops, conditions);
    }

    /** {@return the metrics of one source text} */
    public static CodeMetrics count(Experiment e, String fileName, String source) {
        int lines = source.isEmpty() ? 0 : source.split("\n", -1).length - (source.endsWith("\n") ? 1 : 0);
        // Keep the line breaks of removed comments so that code lines can still be counted.
        Matcher m = COMMENTS_AND_LITERALS.matcher(source);
        StringBuilder code = new StringBuilder();
        while (m.find()) {
            String removed = m.group();
            String keep = removed.startsWith("\"") ? "\"\"" : removed.startsWith("'") ? "' '" : "";
            m.appendReplacement(code, Matcher.quoteReplacement(keep + "\n".repeat(count(removed, '\n'))));
        }
        m.appendTail(code);
        String text = code.toString();
        int codeLines = 0;
        for (String line : text.split("\n")) {
            if (!line.isBlank()) {
                codeLines++;
            }
        }
        int ifs = matches(IF, text), loops = matches(LOOP, text);
        int conditions = ifs + loops + matches(TERNARY, text) + matches(CONNECTIVE, text);
        return new CodeMetrics(e, List.of(fileName), lines, codeLines, ifs, loops, conditions);
    }

    private static int matches(Pattern p, String text) {
        int n = 0;
        for (Matcher m = p.matcher(text); m.find(); ) {
            n++;
        }
        return n;
    }

    private static int count(String s, char c) {
        int n = 0;
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) == c) {
                n++;
            }
        }
        return n;
    }
}
