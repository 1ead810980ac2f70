package jacabot.cartago.bridge;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.runtime.MasLauncher;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * Runs a project folder the way {@code jacabot run FILE.mas2j} does (ProjectClasses, then the
 * MasLauncher, free-running threads), bounded in time, and gives what was printed.
 */
final class ProjectRun {
    final String output;
    final boolean stopped;

    private ProjectRun(String output, boolean stopped) {
        this.output = output;
        this.stopped = stopped;
    }

    List<String> lines() {
        return output.lines().toList();
    }

    /** Writes {@code files} (name to text) into {@code dir}. */
    static void write(Path dir, Map<String, String> files) throws Exception {
        for (var e : files.entrySet()) {
            Path p = dir.resolve(e.getKey());
            Files.createDirectories(p.getParent());
            Files.writeString(p, e.getValue());
        }
    }

    /** Runs until {@code .stopMAS} or {@code timeoutMillis}, with {@code seed}. */
    static ProjectRun run(Path mas2j, long seed, long timeoutMillis) throws Exception {
        var bytes = new ByteArrayOutputStream();
        var out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        ClassLoader before = Thread.currentThread().getContextClassLoader();
        LocalMAS mas;
        try {
            var classes = ProjectClasses.prepare(mas2j, List.of());
            Thread.currentThread().setContextClassLoader(classes.loader());
            mas = new MasLauncher(out, seed, false).load(mas2j);
            var runner = new Thread(() -> {
                try {
                    mas.runThreads();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "project-run");
            runner.start();
            runner.join(timeoutMillis);
            boolean stopped = !runner.isAlive();
            if (!stopped) {
                mas.stop();
                runner.join(5000);
            }
            return new ProjectRun(bytes.toString(StandardCharsets.UTF_8), stopped);
        } finally {
            Thread.currentThread().setContextClassLoader(before);
        }
    }
}
