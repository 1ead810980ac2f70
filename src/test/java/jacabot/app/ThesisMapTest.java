package jacabot.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The plan labels docs/thesis-map.md names exist in the agents (DocsTest checks its paths, classes
 * and commands, not labels): every {@code `@label`} is a plan's label in some
 * {@code agents/src/main/asl/**}{@code /*.asl}, and the labels listed in parentheses right after a
 * skill file, as in {@code `skills/coverage.asl` (`@coverObstacle`, `@movePaused`)}, are that
 * file's or those of a file it includes. {@link #problems(Path)} lists what does not hold, as
 * {@code file:line: what}.
 */
class ThesisMapTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", ".")).toAbsolutePath().normalize();
    private static final String MAP = "docs/thesis-map.md";
    private static final String ASL = "agents/src/main/asl";

    @Test
    void everyPlanLabelTheThesisMapNamesIsInTheFileItNames() throws IOException {
        List<String> problems = problems(ROOT);
        assertTrue(problems.isEmpty(), problems.size() + " plan labels of " + MAP + " are not where it says:\n"
                + String.join("\n", problems));
    }

    @Test
    void aLabelThatIsGoneAndALabelInAnotherSkillAreCaught(@TempDir Path dir) throws IOException {
        Path skills = Files.createDirectories(dir.resolve(ASL).resolve("skills"));
        Files.createDirectories(dir.resolve("docs"));
        Files.writeString(skills.resolve("heading.asl"), "@balanced\n+!balance <- stop.\n");
        Files.writeString(skills.resolve("delivery.asl"), "{ include(\"heading.asl\") }\n@deliverPicked +!go_ahead <- !balance.\n");
        Files.writeString(skills.resolve("picking.asl"), "  @pickCaught[atomic] +!pick <- arm_up.\n");
        Files.writeString(dir.resolve(ASL).resolve("navigation.asl"), "{ include(\"skills/delivery.asl\") }\n");
        Files.writeString(dir.resolve(MAP), String.join("\n",
                "| §3 | `skills/delivery.asl` (`@deliverPicked`, `@balanced`), `navigation.asl` (`@balanced`) | `@OPERATION` |",
                "| §2 | `skills/picking.asl` (`@pickCaught`/`@balanced`; picking's `@deliverPicked`) |",
                "| §2 | `skills/picking.asl`, `@pickGone` |", ""));
        List<String> found = problems(dir);
        assertEquals(2, found.size(), String.join("\n", found));
        assertTrue(found.get(0).equals(MAP + ":2: @balanced is not in skills/picking.asl nor in a file it includes"), found.get(0));
        assertTrue(found.get(1).equals(MAP + ":3: no plan is labelled @pickGone in " + ASL), found.get(1));
    }

    // ---- the check ---------------------------------------------------------------------------

    /** A label in the map: a code span {@code `@name`} (a Java annotation, in capitals, is none). */
    private static final Pattern LABEL = Pattern.compile("`@([A-Za-z][A-Za-z0-9_]*)`");
    /** A plan's label in a source: at the start of a line, before its annotations or trigger. */
    private static final Pattern PLAN_LABEL = Pattern.compile("(?m)^\\s*@([A-Za-z][A-Za-z0-9_]*)");
    private static final Pattern INCLUDE = Pattern.compile("include\\(\"([^\"]+)\"\\)");
    /** A skill file, then the run of labels in parentheses right after it, up to the first other word. */
    private static final Pattern FILE_LABELS = Pattern.compile(
            "`([\\w./-]+\\.asl)`\\s*\\(((?:\\s*`@[A-Za-z][A-Za-z0-9_]*`\\s*[,/]?)+)");

    static List<String> problems(Path root) throws IOException {
        Path asl = root.resolve(ASL);
        Map<Path, Set<String>> own = new HashMap<>();
        Set<String> all = new LinkedHashSet<>();
        try (Stream<Path> s = Files.walk(asl)) {
            for (Path f : s.filter(p -> p.toString().endsWith(".asl")).toList()) {
                Set<String> labels = new LinkedHashSet<>();
                Matcher m = PLAN_LABEL.matcher(Files.readString(f));
                while (m.find()) {
                    labels.add(m.group(1));
                }
                own.put(f.normalize(), labels);
                all.addAll(labels);
            }
        }
        List<String> out = new ArrayList<>();
        List<String> lines = Files.readAllLines(root.resolve(MAP));
        for (int k = 0; k < lines.size(); k++) {
            String line = lines.get(k);
            String where = MAP + ":" + (k + 1) + ": ";
            Matcher l = LABEL.matcher(line);
            while (l.find()) {
                String label = l.group(1);
                if (!label.equals(label.toUpperCase()) && !all.contains(label)) {
                    out.add(where + "no plan is labelled @" + label + " in " + ASL);
                }
            }
            Matcher f = FILE_LABELS.matcher(line);
            while (f.find()) {
                Path file = skillFile(asl, f.group(1), own);
                if (file == null) {
                    continue; // DocsTest reports a path that does not exist
                }
                Set<String> reach = reachable(file, own);
                Matcher fl = LABEL.matcher(f.group(2));
                while (fl.find()) {
                    if (all.contains(fl.group(1)) && !reach.contains(fl.group(1))) {
                        out.add(where + "@" + fl.group(1) + " is not in " + f.group(1) + " nor in a file it includes");
                    }
                }
            }
        }
        return out;
    }

    /** {@return the .asl file a span names: a path under the agents' sources, or a skill's file name} */
    private static Path skillFile(Path asl, String name, Map<Path, Set<String>> own) {
        String rel = name.startsWith(ASL + "/") ? name.substring(ASL.length() + 1) : name;
        for (Path p : List.of(asl.resolve(rel), asl.resolve("skills").resolve(rel))) {
            if (own.containsKey(p.normalize())) {
                return p.normalize();
            }
        }
        return null;
    }

    /** {@return the labels of a file and of every file it includes, transitively (an include is relative to its file)} */
    private static Set<String> reachable(Path file, Map<Path, Set<String>> own) throws IOException {
        Set<String> labels = new LinkedHashSet<>();
        Set<Path> seen = new LinkedHashSet<>();
        List<Path> todo = new ArrayList<>(List.of(file));
        while (!todo.isEmpty()) {
            Path f = todo.remove(todo.size() - 1);
            if (!seen.add(f) || !own.containsKey(f)) {
                continue;
            }
            labels.addAll(own.get(f));
            Matcher m = INCLUDE.matcher(Files.readString(f));
            while (m.find()) {
                todo.add(f.getParent().resolve(m.group(1)).normalize());
            }
        }
        return labels;
    }
}
