package jacabot.cartago.bridge;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaFileObject;
import javax.tools.ToolProvider;

/**
 * Compiles a project's Java sources (its artifacts) with the JDK's own compiler before a run,
 * against jacabot's classes and the project's class path.
 */
public final class SourceCompiler {
    private SourceCompiler() {
    }

    /** The sources do not compile; {@link #lines()} are {@code file:line: message}. */
    public static final class CompileError extends Exception {
        private static final long serialVersionUID = 1L;
        private final List<String> lines;

        CompileError(List<String> lines) {
            super(String.join(System.lineSeparator(), lines));
            this.lines = List.copyOf(lines);
        }

        public List<String> lines() {
            return lines;
        }
    }

    /**
     * Compiles {@code sources} into {@code target}; {@code classpath} is added to the class path
     * jacabot runs with.
     */
    public static void compile(List<Path> sources, List<Path> classpath, Path target) throws CompileError {
        if (sources.isEmpty()) {
            return;
        }
        var compiler = ToolProvider.getSystemJavaCompiler();
        if (compiler == null) {
            throw new CompileError(List.of(sources.get(0) + ": no Java compiler in this Java runtime "
                    + "(run jacabot with a JDK, or compile the classes yourself and use --classpath)"));
        }
        var cp = new ArrayList<String>();
        classpath.forEach(p -> cp.add(p.toString()));
        String own = System.getProperty("java.class.path");
        if (own != null && !own.isEmpty()) {
            cp.add(own);
        }
        var diagnostics = new DiagnosticCollector<JavaFileObject>();
        try (var files = compiler.getStandardFileManager(diagnostics, Locale.ROOT, null)) {
            var units = files.getJavaFileObjectsFromPaths(sources);
            var options = List.of("-d", target.toString(), "-cp", String.join(File.pathSeparator, cp),
                    "-encoding", "UTF-8", "-proc:none", "-nowarn", "-Xlint:none");
            var output = new StringWriter();
            boolean ok = compiler.getTask(output, files, diagnostics, options, null, units).call();
            if (!ok) {
                var lines = new ArrayList<String>();
                for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                    if (d.getKind() == Diagnostic.Kind.ERROR) {
                        lines.add(location(d) + ": " + d.getMessage(Locale.ROOT).lines().findFirst().orElse(""));
                    }
                }
                if (lines.isEmpty()) {
                    lines.add(sources.get(0) + ": compilation failed: " + output.toString().strip());
                }
                throw new CompileError(lines);
            }
        } catch (IOException e) {
            throw new CompileError(List.of(target + ": " + e.getMessage()));
        }
    }

    private static String location(Diagnostic<? extends JavaFileObject> d) {
        String file = d.getSource() == null ? "javac" : shortPath(d.getSource().getName());
        return d.getLineNumber() == Diagnostic.NOPOS ? file : file + ":" + d.getLineNumber();
    }

    /** A path under the working folder is shown relative to it, as the user typed it. */
    private static String shortPath(String name) {
        Path p = Path.of(name).toAbsolutePath().normalize();
        Path cwd = Path.of("").toAbsolutePath();
        return p.startsWith(cwd) ? cwd.relativize(p).toString() : p.toString();
    }
}
