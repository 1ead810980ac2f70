package jacabot.scenario;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.runtime.MasLauncher;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/** A project ({@code .mas2j}) run as {@code jacabot run} runs it, agents on threads, its console kept. */
final class ProjectRun {
    final LocalMAS mas;
    private final ByteArrayOutputStream console;

    private ProjectRun(LocalMAS mas, ByteArrayOutputStream console) {
        this.mas = mas;
        this.console = console;
    }

    /** Runs the project until it stops, or for {@code millis} at most. */
    static ProjectRun of(Path project, long millis) throws Exception {
        var bytes = new ByteArrayOutputStream();
        var mas = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, false).load(project);
        Thread t = new Thread(() -> {
            try {
                mas.runThreads();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        t.setDaemon(true);
        t.start();
        t.join(millis);
        return new ProjectRun(mas, bytes);
    }

    String console() {
        return console.toString(StandardCharsets.UTF_8);
    }
}
