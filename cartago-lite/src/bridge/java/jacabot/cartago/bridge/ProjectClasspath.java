package jacabot.cartago.bridge;

import jacabot.agent.parser.Mas2jLexer;
import jacabot.agent.parser.Mas2jParser;
import jacabot.agent.runtime.MasLauncher;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;

/**
 * Where a project's own classes come from, as Jason's launcher finds them: the {@code classpath:}
 * entries of the {@code .mas2j} (relative to its folder), the entries given on the command line,
 * and the Java sources of the project: every {@code .java} file in the {@code .mas2j}'s folder and
 * its subfolders (as a Jason project's folder is its source root: {@code c4jexamples/Counter.java},
 * {@code src/java}, JaCaMo's {@code src/env}), skipping hidden and build-output folders, and in
 * every {@code classpath:} folder. An entry ending in {@code *}
 * means every jar of that folder, as with {@code java -cp}. A {@code .mas2j} entry that does not
 * exist is ignored with a warning, as Jason and {@code java -cp} ignore it (CArtAgO's examples name
 * {@code ../../../lib/cartago.jar}); a command-line entry that does not exist is an error.
 */
public record ProjectClasspath(List<Path> entries, List<Path> sources, List<String> warnings) {
    public ProjectClasspath {
        entries = List.copyOf(entries);
        sources = List.copyOf(sources);
        warnings = List.copyOf(warnings);
    }

    /** A problem with an entry or a source: one line for the user. */
    public static final class Problem extends Exception {
        private static final long serialVersionUID = 1L;

        public Problem(String message) {
            super(message);
        }
    }

    /**
     * {@return the class path of the project in {@code mas2j} (null for a lone agent file) plus
     * {@code extra}, the command line's entries}
     */
    public static ProjectClasspath of(Path mas2j, List<Path> extra) throws Problem {
        var entries = new LinkedHashSet<Path>();
        var sources = new LinkedHashSet<Path>();
        var warnings = new ArrayList<String>();
        if (mas2j != null && Files.isRegularFile(mas2j)) {   // a missing file: the launcher says so
            Path dir = mas2j.toAbsolutePath().getParent();
            for (String e : classpathEntries(mas2j)) {
                Path p = dir.resolve(e).normalize();
                boolean wildcard = p.getFileName() != null && p.getFileName().toString().equals("*");
                if (!Files.exists(wildcard ? p.getParent() : p)) {
                    warnings.add(mas2j + ": classpath entry '" + e + "' not found, ignored");
                    continue;
                }
                addEntry(p, e, mas2j + ": classpath entry", entries, sources);
            }
            sources.addAll(javaFilesUnder(dir));
        }
        for (Path p : extra) {
            addEntry(p.toAbsolutePath(), p.toString(), "--classpath", entries, sources);
        }
        leaveOutJasonApiSources(sources, warnings);
        return new ProjectClasspath(new ArrayList<>(entries), new ArrayList<>(sources), warnings);
    }

    private static void addEntry(Path p, String given, String where, Set<Path> entries, Set<Path> sources)
            throws Problem {
        p = p.normalize();
        if (p.getFileName() != null && p.getFileName().toString().equals("*")) {
            Path dir = p.getParent();
            if (!Files.isDirectory(dir)) {
                throw new Problem(where + " '" + given + "': no such folder " + dir);
            }
            try (Stream<Path> jars = Files.list(dir)) {
                jars.filter(j -> j.toString().endsWith(".jar")).sorted().forEach(entries::add);
            } catch (IOException e) {
                throw new Problem(where + " '" + given + "': " + e.getMessage());
            }
            return;
        }
        if (!Files.exists(p)) {
            throw new Problem(where + " '" + given + "': no such file or folder " + p);
        }
        entries.add(p);
        if (Files.isDirectory(p)) {
            sources.addAll(javaFilesUnder(p));
        }
    }

    private static boolean isJavaFile(Path p) {
        return Files.isRegularFile(p) && p.getFileName().toString().endsWith(".java");
    }

    /** Folders that hold build output or tools' data, never a project's sources. */
    private static final Set<String> SKIPPED = Set.of("build", "bin", "out", "target", "node_modules");

    private static boolean skipped(Path root, Path p) {
        for (Path part : root.relativize(p)) {
            String name = part.toString();
            if (name.startsWith(".") || SKIPPED.contains(name)) {
                return true;
            }
        }
        return false;
    }

    private static final Pattern JASON_IMPORT = Pattern.compile("(?m)^\\s*import\\s+(?:static\\s+)?(jason\\.[\\w.]*\\*?)");

    /**
     * A source written against Jason's own Java API (an internal action extending Jason's
     * {@code DefaultInternalAction}, an agent architecture, an environment) cannot compile here,
     * where that API does not exist: it is left out with one warning, as Jason leaves out a class
     * it cannot load, and the program runs without it (an action it would have defined goes to the
     * environment).
     */
    private static void leaveOutJasonApiSources(Set<Path> sources, List<String> warnings) throws Problem {
        for (var it = sources.iterator(); it.hasNext(); ) {
            Path source = it.next();
            String text;
            try {
                text = Files.readString(source, StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new Problem(source + ": " + e.getMessage());
            }
            Matcher m = JASON_IMPORT.matcher(text);
            if (m.find()) {
                it.remove();
                Path cwd = Path.of("").toAbsolutePath();
                Path shown = source.startsWith(cwd) ? cwd.relativize(source) : source;
                warnings.add(shown + ":" + lineOf(text, m.start(1)) + ": warning: imports " + m.group(1)
                        + " of Jason's own Java API, which jacabot does not provide: not compiled, its classes are missing");
            }
        }
    }

    private static int lineOf(String text, int offset) {
        int line = 1;
        for (int i = 0; i < offset; i++) {
            if (text.charAt(i) == '\n') {
                line++;
            }
        }
        return line;
    }

    private static List<Path> javaFilesUnder(Path dir) throws Problem {
        try (Stream<Path> files = Files.walk(dir)) {
            return files.filter(p -> isJavaFile(p) && !skipped(dir, p.getParent())).sorted().toList();
        } catch (IOException e) {
            throw new Problem(dir + ": " + e.getMessage());
        }
    }

    /**
     * The strings of the {@code classpath:} settings. A file that does not parse gives none: the
     * launcher reports its syntax errors.
     */
    static List<String> classpathEntries(Path mas2j) throws Problem {
        if (mas2j.getFileName().toString().endsWith(".jcm")) {
            try {
                return JcmReader.classPath(mas2j);
            } catch (MasLauncher.UserError e) {
                return List.of(); // the launcher reports it
            }
        }
        String text;
        try {
            text = Files.readString(mas2j, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new Problem(mas2j + ": " + e.getMessage());
        }
        var lexer = new Mas2jLexer(CharStreams.fromString(text));
        lexer.removeErrorListeners();
        var parser = new Mas2jParser(new CommonTokenStream(lexer));
        parser.removeErrorListeners();
        var failed = new boolean[1];
        parser.addErrorListener(new BaseErrorListener() {
            @Override
            public void syntaxError(Recognizer<?, ?> r, Object o, int line, int col, String msg,
                    RecognitionException e) {
                failed[0] = true;
            }
        });
        var tree = parser.project();
        var out = new ArrayList<String>();
        if (failed[0]) {
            return out;
        }
        for (Mas2jParser.SettingContext s : tree.setting()) {
            if (s instanceof Mas2jParser.ClasspathContext c) {
                c.STRING().forEach(t -> {
                    String q = t.getText();
                    out.add(q.substring(1, q.length() - 1));
                });
            }
        }
        return out;
    }
}
