package jacabot.app.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

/**
 * Our interpreter against Jason 3.2.0 on the same AgentSpeak programs. Each run is a fresh JVM with
 * the same options; a run's time is from the program's {@code start} line to its {@code end} line
 * (JVM start-up and Jason's shutdown are not counted). Runs alternate between the two
 * interpreters, after one discarded warm-up run each. Peak memory is the process' maximum
 * resident set (GNU time), reasoning cycles are counted by our interpreter.
 */
public final class InterpreterBenchmark {
    /** The programs: name, project file, what it does. */
    public static final List<String[]> PROGRAMS = List.of(
            new String[] {"count", "count.mas2j", "200 000 tail-recursive !count(N) subgoals"},
            new String[] {"beliefs", "beliefs.mas2j", "200 000 +v(I)/-v(I) pairs in a for"},
            new String[] {"counter", "counter.mas2j", "while loop of 200 000 -+counter(N)"},
            new String[] {"rules", "rules.mas2j", "recursive ancestor rule over 1 000 facts, 10 000 queries"},
            new String[] {"messages", "messages.mas2j", "20 000 .send tell between two agents"},
            new String[] {"agents", "many.mas2j", "1 000 agents each counting to 1 000"});
    private static final String[] FILES = {"count.asl", "count.mas2j", "beliefs.asl", "beliefs.mas2j", "counter.asl",
        "counter.mas2j", "rules.asl", "rules.mas2j", "sender.asl", "receiver.asl", "messages.mas2j", "worker.asl",
        "supervisor.asl", "many.mas2j"};
    private static final String JASON_LOGGING = String.join("\n",
            "handlers = java.util.logging.ConsoleHandler", ".level = INFO",
            "java.util.logging.ConsoleHandler.level = FINE",
            "java.util.logging.ConsoleHandler.formatter = jason.runtime.MASConsoleLogFormatter", "java.level=OFF",
            "javax.level=OFF", "sun.level=OFF", "");

    /** One measured run. */
    record Run(double seconds, long peakKb, long cycles) {
    }

    private final String ourClasspath;
    private final String jasonClasspath;
    private final int runs;
    private final PrintStream out;
    private final Path dir;

    public InterpreterBenchmark(String ourClasspath, String jasonClasspath, int runs, PrintStream out) throws IOException {
        this.ourClasspath = ourClasspath;
        this.jasonClasspath = jasonClasspath;
        this.runs = runs;
        this.out = out;
        this.dir = Files.createTempDirectory("jacabot-bench");
        for (String f : FILES) {
            try (InputStream in = InterpreterBenchmark.class.getResourceAsStream("/bench/" + f)) {
                Files.copy(in, dir.resolve(f));
            }
        }
        Files.writeString(dir.resolve("jason-logging.properties"), JASON_LOGGING);
    }

    public void run() throws IOException, InterruptedException {
        out.println("| program | ours (s) | Jason (s) | Jason / ours | our cycles/s | Jason cycles/s | our peak memory (MB) | Jason peak memory (MB) |");
        out.println("|---|---|---|---|---|---|---|---|");
        for (String[] p : PROGRAMS) {
            ours(p[1]);
            jason(p[1]);
            var ours = new ArrayList<Run>();
            var jason = new ArrayList<Run>();
            for (int i = 0; i < runs; i++) {
                ours.add(ours(p[1]));
                jason.add(jason(p[1]));
            }
            Run o = median(ours);
            Run j = median(jason);
            long cycles = o.cycles;
            out.printf(Locale.ROOT, "| %s (%s) | %.3f | %.3f | %.2f | %,.0f | %,.0f | %d | %d |%n", p[0], p[2], o.seconds,
                    j.seconds, j.seconds / o.seconds, cycles / o.seconds, cycles / j.seconds, o.peakKb / 1024, j.peakKb / 1024);
        }
    }

    private Run ours(String project) throws IOException, InterruptedException {
        return measure(List.of("-cp", ourClasspath, "jacabot.app.cli.JacabotCommand", "run", "--stats", project));
    }

    private Run jason(String project) throws IOException, InterruptedException {
        return measure(List.of("-cp", jasonClasspath, "jason.infra.local.RunLocalMAS", project, "--log-conf",
                "jason-logging.properties"));
    }

    private static Run median(List<Run> rs) {
        Run[] a = rs.toArray(new Run[0]);
        Arrays.sort(a, (x, y) -> Double.compare(x.seconds, y.seconds));
        return a[a.length / 2];
    }

    private Run measure(List<String> javaArgs) throws IOException, InterruptedException {
        Path timeFile = dir.resolve("time.txt");
        var cmd = new ArrayList<String>();
        boolean gnuTime = Files.isExecutable(Path.of("/usr/bin/time"));
        if (gnuTime) {
            cmd.addAll(List.of("/usr/bin/time", "-f", "%M", "-o", timeFile.toString()));
        }
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Djava.awt.headless=true");
        cmd.addAll(javaArgs);
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).start();
        long start = -1;
        long end = -1;
        long cycles = 0;
        try (var r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = r.readLine()) != null) {
                long now = System.nanoTime();
                if (line.endsWith("] start") && start < 0) {
                    start = now;
                } else if (line.endsWith("] end")) {
                    end = now;
                } else if (line.startsWith("cycles ")) {
                    cycles = Long.parseLong(line.substring(7).trim());
                }
            }
        }
        if (!p.waitFor(10, TimeUnit.MINUTES)) {
            p.destroyForcibly();
        }
        if (start < 0 || end < 0) {
            throw new IOException("the program did not print its start and end lines: " + String.join(" ", cmd));
        }
        long peak = gnuTime ? Long.parseLong(Files.readString(timeFile).trim().lines().reduce((a, b) -> b).orElse("0")) : 0;
        return new Run((end - start) / 1e9, peak, cycles);
    }
}
