package jacabot.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.cli.JacabotCommand;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileSystems;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * What the documents name exists: README.md, the module READMEs, the examples' READMEs and
 * docs/*.md. Each repository path they name (in a link, a code span or a code block) resolves in
 * the repository, each class named {@code jacabot.x.Y} has its source file, and each
 * {@code jacabot ...} command parses with the launcher's picocli spec (not run).
 * {@link #problems(Path)} lists what does not, as {@code file:line: what}.
 */
class DocsTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", ".")).toAbsolutePath().normalize();

    @Test
    void everyPathClassAndCommandTheDocumentsNameExists() throws IOException {
        List<String> problems = problems(ROOT);
        assertTrue(problems.isEmpty(), problems.size() + " names in the documents do not exist:\n" + String.join("\n", problems));
    }

    @Test
    void aMovedPathAClassThatIsGoneAndABadOptionAreCaught(@TempDir Path dir) throws IOException {
        Files.createDirectories(dir.resolve("docs"));
        Files.createDirectories(dir.resolve("robot-link/src/main/java/jacabot/robot/link"));
        Files.writeString(dir.resolve("robot-link/src/main/java/jacabot/robot/link/SensorInfo.java"), "class SensorInfo {}");
        Files.writeString(dir.resolve("docs/map.md"), String.join("\n",
                "The readings: `robot-controller/.../link/SensorInfo.java`; now `robot-link/.../link/SensorInfo.java`.",
                "The class `jacabot.robot.link.SensorInfo` and `jacabot.robot.link.Gone`.",
                "```", "jacabot experiment navigation --headles", "jacabot experiment navigation --headless", "```",
                "[the map](map.md), [nothing](none.md)",
                "`jacabot world generate team-delivery --robots 2`, `jacabot world generate`, `jacabot run --tls-store`", ""));
        List<String> found = problems(dir);
        assertTrue(found.size() == 5, String.join("\n", found));
        assertTrue(found.get(0).startsWith("docs/map.md:1: no such path: robot-controller/.../link/SensorInfo.java"), found.get(0));
        assertTrue(found.get(1).startsWith("docs/map.md:2: no source for class jacabot.robot.link.Gone"), found.get(1));
        assertTrue(found.get(2).startsWith("docs/map.md:4: `jacabot experiment navigation --headles` does not parse"), found.get(2));
        assertTrue(found.get(3).startsWith("docs/map.md:7: no such path: none.md"), found.get(3));
        // a required option left out of a command given its arguments, not a command named alone or an option's value
        assertTrue(found.get(4).startsWith("docs/map.md:8: `jacabot world generate team-delivery --robots 2` does not parse: "
                + "Missing required option: '--seed=N'"), found.get(4));
    }

    // ---- the check ---------------------------------------------------------------------------

    private static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s]+)\\)");
    private static final Pattern SPAN = Pattern.compile("`([^`]+)`");
    private static final Pattern CLASS = Pattern.compile("(?<![\\w.-])jacabot(?:\\.[a-z][a-z0-9_]*)+(?:\\.[A-Z][A-Za-z0-9_]*)+");
    /** Folders and files at the top of the repository a path may start with. */
    private static final List<String> TOP = List.of("src", "docs", "worlds", "examples", "agents", "agent-core", "cartago-lite",
            "robot-controller", "robot-link", "sim-world", "gradle", "README.md", "build.gradle", "settings.gradle",
            "gradle.properties");
    /** Placeholders of a command's synopsis and the values that stand for them when it is parsed. */
    private static final Map<String, String> SAMPLE = Map.of("NAME", "navigation", "EXPERIMENT", "navigation", "E", "navigation",
            "I/N", "1/2");

    /** {@return the documents checked: README.md, the modules' and examples' READMEs, docs/*.md} */
    static List<Path> documents(Path root) throws IOException {
        List<Path> docs = new ArrayList<>();
        if (Files.isRegularFile(root.resolve("README.md"))) {
            docs.add(root.resolve("README.md"));
        }
        for (String dir : List.of(".", "examples", "docs")) {
            if (!Files.isDirectory(root.resolve(dir))) {
                continue;
            }
            try (Stream<Path> s = Files.list(root.resolve(dir))) {
                s.sorted().forEach(p -> {
                    if (dir.equals("docs") && p.toString().endsWith(".md")) {
                        docs.add(p);
                    } else if (!dir.equals("docs") && Files.isRegularFile(p.resolve("README.md"))) {
                        docs.add(p.resolve("README.md"));
                    }
                });
            }
        }
        return docs;
    }

    /** Every file and folder of the repository but its outputs (build/, runs/) and hidden folders, relative to it. */
    private static List<Path> index(Path root) throws IOException {
        List<Path> files = new ArrayList<>();
        Files.walkFileTree(root, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                String name = dir.getFileName() == null ? "" : dir.getFileName().toString();
                if (!dir.equals(root) && (name.startsWith(".") || name.equals("build") || name.equals("runs"))) {
                    return FileVisitResult.SKIP_SUBTREE;
                }
                files.add(root.relativize(dir));
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                files.add(root.relativize(file));
                return FileVisitResult.CONTINUE;
            }
        });
        return files;
    }

    static List<String> problems(Path root) throws IOException {
        Map<String, Boolean> classes = new HashMap<>();
        List<Path> files = index(root);
        List<String> out = new ArrayList<>();
        for (Path doc : documents(root)) {
            String name = root.relativize(doc).toString();
            List<String> lines = Files.readAllLines(doc);
            boolean block = false;
            for (int k = 0; k < lines.size(); k++) {
                String line = lines.get(k);
                String where = name + ":" + (k + 1) + ": ";
                if (line.strip().startsWith("```")) {
                    block = !block;
                    continue;
                }
                List<String> code = new ArrayList<>();
                if (block) {
                    String cmd = line;
                    while (cmd.endsWith("\\") && k + 1 < lines.size()) { // a command continued on the next line
                        cmd = cmd.substring(0, cmd.length() - 1) + " " + lines.get(++k).strip();
                    }
                    code.add(cmd);
                    command(cmd.strip().replaceFirst("^\\$ ", ""), false).ifPresent(c -> parse(launcherFor(c), c, false, where, out));
                } else {
                    // a span that is the text of a link to another site names that site's file, not ours
                    Matcher m = SPAN.matcher(line.replaceAll("\\[`[^`]*`\\]\\((https?|mailto):[^)]*\\)", ""));
                    while (m.find()) {
                        code.add(m.group(1));
                        command(m.group(1), true).ifPresent(c -> parse(launcherFor(c), c, true, where, out));
                    }
                    Matcher l = LINK.matcher(line);
                    while (l.find()) {
                        String target = l.group(1).replaceFirst("#.*", "");
                        if (!target.isEmpty() && !target.contains("://") && !target.startsWith("mailto:")
                                && !Files.exists(doc.getParent().resolve(target))) {
                            out.add(where + "no such path: " + target);
                        }
                    }
                }
                for (String c : code) {
                    for (String token : c.split("[\\s,;()=\"'<>]+")) {
                        String p = token.replaceAll("^[`*]+|[`*.:]+$", "").replaceFirst("(:\\d+)+$", "");
                        if (isRepositoryPath(p) && !resolves(root, root.relativize(doc.getParent()), p, files)) {
                            out.add(where + "no such path: " + p);
                        }
                    }
                }
                Matcher c = CLASS.matcher(line);
                while (c.find()) {
                    String cls = c.group();
                    if (!classes.computeIfAbsent(cls, q -> hasSource(root, q, files))) {
                        out.add(where + "no source for class " + cls);
                    }
                }
            }
        }
        return out;
    }

    /** A path in the repository: starts with a top folder or ./ or ../, names no output (build/, runs/) nor placeholder only. */
    private static boolean isRepositoryPath(String p) {
        if (!p.contains("/") || p.contains("://") || p.startsWith("/") || p.startsWith("~") || p.contains("$") || p.contains("*")
                || p.contains("{")) {
            return false;
        }
        String first = p.replaceFirst("^(\\./|\\.\\./)+", "").split("/")[0];
        return TOP.contains(first);
    }

    /**
     * Resolves against the document's folder, then the repository's; {@code ...} stands for any
     * folders, CAPITALS and {@code <x>} for any name.
     */
    private static boolean resolves(Path root, Path docDir, String p, List<Path> files) {
        String glob = p.replace("/.../", "/**/").replaceAll("<[^>]*>", "*")
                .replaceAll("\\b(?!README\\b)[A-Z][A-Z0-9_]*\\b", "*").replaceFirst("/$", "");
        for (Path base : List.of(docDir, Path.of(""))) {
            Path rel = base.resolve(glob).normalize();
            if (rel.startsWith("..")) {
                continue;
            }
            if (glob.equals(p.replaceFirst("/$", ""))) {
                if (Files.exists(root.resolve(rel))) {
                    return true;
                }
                continue;
            }
            var matcher = FileSystems.getDefault().getPathMatcher("glob:" + rel);
            if (files.stream().anyMatch(matcher::matches)) {
                return true;
            }
        }
        return false;
    }

    /** A class has a source file in some module: {@code jacabot.x.Y} or its nested {@code jacabot.x.Y.Z}. */
    private static boolean hasSource(Path root, String qualified, List<Path> files) {
        String[] parts = qualified.split("\\.");
        int top = 0;
        while (top < parts.length && !Character.isUpperCase(parts[top].charAt(0))) {
            top++;
        }
        String file = "/java/" + String.join("/", List.of(parts).subList(0, top + 1)) + ".java";
        boolean nested = top < parts.length - 1;
        Pattern member = Pattern.compile("\\b(class|record|interface|enum) " + parts[parts.length - 1] + "\\b");
        for (Path f : files) {
            if (("/" + f).endsWith(file)) {
                try {
                    if (!nested || member.matcher(Files.readString(root.resolve(f))).find()) {
                        return true;
                    }
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }
        }
        return false;
    }

    /**
     * The launcher's arguments in a code line: after {@code jacabot} or {@code .../bin/jacabot}, up to a
     * comment, a pipe or a redirection. A synopsis ({@code [--seed N]}, {@code a|b}, {@code NAME}) is
     * read with its options taken, its first alternatives and sample values for its placeholders.
     */
    static Optional<List<String>> command(String line, boolean span) {
        String text = line.replace("\\|", "|");
        Matcher m = Pattern.compile("(?:^|\\s)(?:[\\w./-]*/bin/)?jacabot((?:\\s.*)?)$").matcher(text);
        if (!m.find() || (span && m.start() != 0) || text.startsWith("jacabot.")) {
            return Optional.empty();
        }
        String rest = m.group(1).replaceFirst("\\s#.*", "").replaceFirst("\\s(\\||&&|>|2>|;|:::).*", "");
        rest = rest.replace("[no-]", "no-").replaceAll("<[^>]*>", "NAME").replaceAll("\\|[^\\s\\]]*", "").replace("[", " ").replace("]", " ").replace("{}", "1")
                .replaceAll("\"?\\$[A-Za-z_]+\"?", "1");
        List<String> args = new ArrayList<>();
        for (String t : rest.trim().split("\\s+")) {
            if (t.isEmpty() || t.equals("...") || t.equals("…")) {
                continue;
            }
            String u = t.replaceAll("^\"|\"$", "");
            args.add(SAMPLE.getOrDefault(u, u.matches("[A-Z]{1,2}") ? "1" : u));
        }
        return Optional.of(args);
    }

    /** {@return the launcher as it parses these arguments (the team's experiment and sweep are commands of their own)} */
    private static CommandLine launcherFor(List<String> args) {
        return JacabotCommand.commandLine(args.toArray(new String[0]));
    }

    /**
     * A span may name a command without all it needs (`jacabot run`, `jacabot run --tls-store`); a
     * code line may not, nor a span that gives its command arguments but leaves out a required
     * option (`jacabot world generate team-delivery --robots N` without its --seed).
     */
    private static void parse(CommandLine launcher, List<String> args, boolean partial, String where, List<String> out) {
        try {
            launcher.parseArgs(args.toArray(new String[0]));
        } catch (CommandLine.MissingParameterException e) {
            if (!partial || leavesOutARequiredOption(e, args)) {
                out.add(where + "`jacabot " + String.join(" ", args) + "` does not parse: " + e.getMessage());
            }
        } catch (CommandLine.ParameterException e) {
            out.add(where + "`jacabot " + String.join(" ", args) + "` does not parse: " + e.getMessage());
        }
    }

    /** {@return whether the command is given arguments and a required option it leaves out is not named among them} */
    private static boolean leavesOutARequiredOption(CommandLine.MissingParameterException e, List<String> args) {
        int at = args.indexOf(e.getCommandLine().getCommandName());
        if (at < 0 || at == args.size() - 1) {
            return false; // the command named alone
        }
        return e.getMissing().stream().anyMatch(a -> a instanceof CommandLine.Model.OptionSpec o
                && java.util.Arrays.stream(o.names()).noneMatch(n -> args.stream().anyMatch(x -> x.equals(n) || x.startsWith(n + "="))));
    }
}
