package jacabot.cartago.bridge;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * A project's own classes, ready to load: its sources compiled into a temporary folder (removed
 * when the JVM ends), and a class loader over that folder and the class path, whose parent is
 * jacabot's loader. {@code makeArtifact("c", "my.Counter")} finds its classes through it.
 */
public final class ProjectClasses {
    private final ProjectClasspath classpath;
    private final ClassLoader loader;
    private final Path compiled;

    private ProjectClasses(ProjectClasspath classpath, ClassLoader loader, Path compiled) {
        this.classpath = classpath;
        this.loader = loader;
        this.compiled = compiled;
    }

    /**
     * Finds, compiles and loads the classes of the project in {@code mas2j} (null for none) and
     * of the {@code extra} entries.
     */
    public static ProjectClasses prepare(Path mas2j, List<Path> extra)
            throws ProjectClasspath.Problem, SourceCompiler.CompileError {
        ProjectClasspath cp = ProjectClasspath.of(mas2j, extra);
        ClassLoader parent = ProjectClasses.class.getClassLoader();
        if (cp.entries().isEmpty() && cp.sources().isEmpty()) {
            return new ProjectClasses(cp, parent, null);
        }
        Path out = null;
        var urls = new ArrayList<URL>();
        try {
            if (!cp.sources().isEmpty()) {
                out = Files.createTempDirectory("jacabot-classes");
                deleteOnExit(out);
                SourceCompiler.compile(cp.sources(), cp.entries(), out);
                urls.add(out.toUri().toURL());
            }
            for (Path p : cp.entries()) {
                urls.add(p.toUri().toURL());
            }
        } catch (IOException e) {
            throw new ProjectClasspath.Problem("cannot prepare the project's classes: " + e.getMessage());
        }
        var loader = new URLClassLoader("jacabot-project", urls.toArray(new URL[0]), parent);
        return new ProjectClasses(cp, loader, out);
    }

    /** {@return the loader of the project's classes (jacabot's own loader when it has none)} */
    public ClassLoader loader() {
        return loader;
    }

    public ProjectClasspath classpath() {
        return classpath;
    }

    /** {@return the folder holding the compiled sources, or null if there were none} */
    public Path compiledClasses() {
        return compiled;
    }

    private static void deleteOnExit(Path dir) {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            try (Stream<Path> files = Files.walk(dir)) {
                files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            } catch (IOException | UncheckedIOException e) {
                // a temporary folder left behind is harmless
            }
        }, "jacabot-classes-cleanup"));
    }
}
