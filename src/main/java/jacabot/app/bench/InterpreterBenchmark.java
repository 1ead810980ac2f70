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
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Our interpreter against Jason 3.2.0 on the same AgentSpeak programs. Each run is a fresh JVM with
 * the same options, and ours also maps the class-data sharing archive its launcher passes (when
 * the class path's folder has one that this JVM can use). A run has two times: from the program's
 * {@code start} line to its {@code end} line (JVM start-up and shutdown not counted), and the
 * whole process, from its start to its exit. Runs alternate between the two
 * interpreters, after one discarded warm-up run each. Peak memory is the process' maximum
 * resident set (GNU time), reasoning cycles are counted by our interpreter. The deep recursion
 * programs ({@link #DEEP}) are timed the same way, with a time limit per run, and a second table
 * tells how time and memory grow with the depth of the proofs.
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
    /** A deep recursion program: a copy of {@code resource} with this chain length and query count. */
    record Deep(String name, String resource, int length, int queries, String what) {
    }

    /** Rule proofs as deep as a chain of facts: the chain series (100 to 1 600), backtracking, many queries. */
    public static final List<Deep> DEEP = List.of(
            new Deep("ancestor-100", "ancestor.asl", 100, 200, "ancestor/2 end to end over a 100-long chain, 200 queries"),
            new Deep("ancestor-200", "ancestor.asl", 200, 200, "the same over a 200-long chain"),
            new Deep("ancestor-400", "ancestor.asl", 400, 200, "the same over a 400-long chain"),
            new Deep("ancestor-800", "ancestor.asl", 800, 200, "the same over an 800-long chain"),
            new Deep("ancestor-1600", "ancestor.asl", 1600, 200, "the same over a 1 600-long chain"),
            new Deep("branches", "branches.asl", 100, 40,
                    "ancestor/2 over a 100-long chain with 5 dead ends tried first at each link, 40 queries"),
            new Deep("ancestor-300x2000", "ancestor.asl", 300, 2000, "ancestor/2 end to end over a 300-long chain, 2 000 queries"));
    /** A run longer than this is its program's only measured run (the deep programs on a quadratic solver). */
    private static final double LONG_RUN_SECONDS = 20;
    private static final String[] FILES = {"count.asl", "count.mas2j", "beliefs.asl", "beliefs.mas2j", "counter.asl",
        "counter.mas2j", "rules.asl", "rules.mas2j", "sender.asl", "receiver.asl", "messages.mas2j", "worker.asl",
        "supervisor.asl", "many.mas2j", "ancestor.asl", "branches.asl"};
    private static final String JASON_LOGGING = String.join("\n",
            "handlers = java.util.logging.ConsoleHandler", ".level = INFO",
            "java.util.logging.ConsoleHandler.level = FINE",
            "java.util.logging.ConsoleHandler.formatter = jason.runtime.MASConsoleLogFormatter", "java.level=OFF",
            "javax.level=OFF", "sun.level=OFF", "");

    /** One measured run: {@code seconds} from start to end line, {@code wholeSeconds} the process; cut at the time limit: {@code timedOut}. */
    record Run(double seconds, double wholeSeconds, long peakKb, long cycles, boolean timedOut) {
        static final Run NONE = new Run(Double.NaN, Double.NaN, 0, 0, true);
    }

    /**
     * The JIT option {@code bin/jacabot} gives {@code run} and {@code test} (the start script's,
     * {@code agentSpeakJit} in the build): C1 only, so that a run of seconds does not pay C2's compiling.
     */
    public static final String RUN_JIT = "-XX:TieredStopAtLevel=1";

    private final String ourClasspath;
    /** The JVM options our runs add: the launcher's class-data sharing archive, when usable. */
    private final List<String> ourJavaOptions;
    private final String jasonClasspath;
    private final int runs;
    private final PrintStream out;
    private final Path dir;
    private final Set<String> selected;
    private final double limitSeconds;
    private final List<Path> projects;
    /** Why the user's projects that could not be measured were not: said once every row is printed. */
    private final List<String> failedProjects = new ArrayList<>();

    public InterpreterBenchmark(String ourClasspath, String jasonClasspath, int runs, PrintStream out) throws IOException {
        this(ourClasspath, jasonClasspath, runs, out, null, 300, List.of());
    }

    /**
     * @param programs the programs to run by name ({@code deep} for all of {@link #DEEP}), or null for all
     * @param limitSeconds the longest a deep program's run may take; longer chains are then not run
     * @param projects the user's own projects ({@code .mas2j}) to run too, each in its directory; an
     *        agent prints {@code start} and {@code end} around what is measured
     */
    public InterpreterBenchmark(String ourClasspath, String jasonClasspath, int runs, PrintStream out,
            Set<String> programs, double limitSeconds, List<Path> projects) throws IOException {
        this.projects = List.copyOf(projects);
        this.ourClasspath = ourClasspath;
        this.ourJavaOptions = SharedArchive.optionsFor(ourClasspath);
        this.jasonClasspath = jasonClasspath;
        this.runs = runs;
        this.out = out;
        this.selected = programs;
        this.limitSeconds = limitSeconds;
        this.dir = Files.createTempDirectory("jacabot-bench");
        for (String f : FILES) {
            try (InputStream in = InterpreterBenchmark.class.getResourceAsStream("/bench/" + f)) {
                Files.copy(in, dir.resolve(f));
            }
        }
        Files.writeString(dir.resolve("jason-logging.properties"), JASON_LOGGING);
        for (Deep d : DEEP) {
            // Jason's project files take no '-' in names
            String file = d.name().replace('-', '_');
            Files.writeString(dir.resolve(file + ".asl"), variant(Files.readString(dir.resolve(d.resource())), d));
            Files.writeString(dir.resolve(file + ".mas2j"), "MAS " + file + " { agents: " + file + " " + file + ".asl; }\n");
        }
    }

    /** {@return the names of every program, the deep ones included} */
    public static List<String> names() {
        var names = new ArrayList<String>();
        PROGRAMS.forEach(p -> names.add(p[0]));
        DEEP.forEach(d -> names.add(d.name()));
        return names;
    }

    /** {@return the program with the deep program's chain length and query count} */
    static String variant(String program, Deep d) {
        return program.replaceFirst("(?m)^length\\(\\d+\\)\\.", "length(" + d.length() + ").")
                .replaceFirst("(?m)^queries\\(\\d+\\)\\.", "queries(" + d.queries() + ").");
    }

    private boolean wanted(String name) {
        return selected == null || selected.contains(name)
                || selected.contains("deep") && DEEP.stream().anyMatch(d -> d.name().equals(name));
    }

    public void run() throws IOException, InterruptedException {
        if (PROGRAMS.stream().anyMatch(p -> wanted(p[0])) || !projects.isEmpty()) {
            programs();
        }
        if (DEEP.stream().anyMatch(d -> wanted(d.name()))) {
            deep();
        }
        if (!failedProjects.isEmpty()) {
            throw new IOException(String.join("; ", failedProjects));
        }
    }


    private void programs() throws IOException, InterruptedException {
        out.println(ourJavaOptions.isEmpty() ? "Our runs without a class-data sharing archive."
                : "Our runs with the launcher's class-data sharing archive (" + ourJavaOptions.get(0) + ").");
        out.println();
        out.println("| program | ours (s) | Jason (s) | Jason / ours | our cycles/s | Jason cycles/s | our peak memory (MB) | Jason peak memory (MB)"
                + " | ours, whole process (s) | Jason, whole process (s) | Jason / ours, whole process |");
        out.println("|---|---|---|---|---|---|---|---|---|---|---|");
        for (String[] p : PROGRAMS) {
            if (!wanted(p[0])) {
                continue;
            }
            row(p[0] + " (" + p[2] + ")", dir.resolve(p[1]));
        }
        for (Path project : projects) {
            String name = project.getFileName().toString();
            try {
                row(name, project.toAbsolutePath());
            } catch (IOException e) {
                // the other projects are still measured; the run ends in this error
                failedProjects.add(e.getMessage());
                out.printf("| %s | – | – | – | – | – | – | – | – | – | – |%n", name);
            }
        }
    }

    /** Measures one project on both interpreters, alternating after a warm-up run each, and prints its row. */
    private void row(String name, Path project) throws IOException, InterruptedException {
        ours(project);
        jason(project);
        var ours = new ArrayList<Run>();
        var jason = new ArrayList<Run>();
        for (int i = 0; i < runs; i++) {
            ours.add(ours(project));
            jason.add(jason(project));
        }
        Run o = median(ours);
        Run j = median(jason);
        double oWhole = medianWhole(ours);
        double jWhole = medianWhole(jason);
        long cycles = o.cycles;
        out.printf(Locale.ROOT, "| %s | %.3f | %.3f | %.2f | %,.0f | %,.0f | %d | %d | %.3f | %.3f | %.2f |%n", name, o.seconds,
                j.seconds, j.seconds / o.seconds, cycles / o.seconds, cycles / j.seconds, o.peakKb / 1024, j.peakKb / 1024,
                oWhole, jWhole, jWhole / oWhole);
    }

    /**
     * The deep programs: one row each, then how the chain series grows. Each interpreter's first run
     * is a warm-up unless it took longer than {@link #LONG_RUN_SECONDS} (then it is the only run);
     * a run cut at the limit skips that interpreter's longer chains.
     */
    private void deep() throws IOException, InterruptedException {
        out.println();
        out.println("| deep recursion program | ours (s) | Jason (s) | Jason / ours | our peak memory (MB) | Jason peak memory (MB) |");
        out.println("|---|---|---|---|---|---|");
        var series = new LinkedHashMap<Integer, Run[]>();
        boolean oursCut = false;
        boolean jasonCut = false;
        for (Deep d : DEEP) {
            if (!wanted(d.name())) {
                continue;
            }
            boolean chain = d.name().startsWith("ancestor-") && d.queries() == 200;
            Path project = dir.resolve(d.name().replace('-', '_') + ".mas2j");
            Run o = oursCut && chain ? Run.NONE : deepRuns(true, project);
            Run j = jasonCut && chain ? Run.NONE : deepRuns(false, project);
            if (chain) {
                oursCut |= o.timedOut;
                jasonCut |= j.timedOut;
                series.put(d.length(), new Run[] {o, j});
            }
            out.printf(Locale.ROOT, "| %s (%s) | %s | %s | %s | %s | %s |%n", d.name(), d.what(), seconds(o), seconds(j),
                    o.timedOut || j.timedOut ? "–" : String.format(Locale.ROOT, "%.2f", j.seconds / o.seconds),
                    megabytes(o), megabytes(j));
        }
        Run[] first = series.get(100);
        if (first == null || series.size() < 2) {
            return;
        }
        out.println();
        out.println("Growth with the depth of the proofs, from the 100-long chain: (time or peak memory at length L ÷ at 100) ÷ (L ÷ 100);"
                + " 1 or less is linear, and a solver quadratic in the depth doubles it with each doubling of L.");
        out.println();
        out.println("| chain length | ours: time | ours: peak memory | Jason: time | Jason: peak memory |");
        out.println("|---|---|---|---|---|");
        series.forEach((length, r) -> out.printf(Locale.ROOT, "| %,d | %s | %s | %s | %s |%n", length,
                growth(r[0].seconds, first[0].seconds, r[0].timedOut, length), growth(r[0].peakKb, first[0].peakKb, r[0].timedOut, length),
                growth(r[1].seconds, first[1].seconds, r[1].timedOut, length), growth(r[1].peakKb, first[1].peakKb, r[1].timedOut, length)));
    }

    private Run deepRuns(boolean ours, Path project) throws IOException, InterruptedException {
        Run warmUp = ours ? ours(project) : jason(project);
        if (warmUp.timedOut || warmUp.seconds > LONG_RUN_SECONDS) {
            return warmUp;
        }
        var measured = new ArrayList<Run>();
        for (int i = 0; i < runs; i++) {
            measured.add(ours ? ours(project) : jason(project));
        }
        return median(measured);
    }

    private String seconds(Run r) {
        return r == Run.NONE ? "not run" : r.timedOut ? String.format(Locale.ROOT, "> %.0f", limitSeconds)
                : String.format(Locale.ROOT, "%.3f", r.seconds);
    }

    private static String megabytes(Run r) {
        return r.timedOut ? "–" : Long.toString(r.peakKb / 1024);
    }

    private static String growth(double value, double atHundred, boolean timedOut, int length) {
        return timedOut ? "–" : String.format(Locale.ROOT, "%.2f", value / atHundred / (length / 100.0));
    }

    /** Runs a project (a {@code .mas2j}) in its directory, as its user would with {@code bin/jacabot run}. */
    private Run ours(Path project) throws IOException, InterruptedException {
        var args = new ArrayList<>(ourJavaOptions);
        args.add(RUN_JIT);
        args.addAll(List.of("-cp", ourClasspath, "jacabot.app.cli.JacabotCommand", "run", "--stats", project.getFileName().toString()));
        return measure("our interpreter", project, args);
    }

    private Run jason(Path project) throws IOException, InterruptedException {
        return measure("Jason", project, List.of("-cp", jasonClasspath, "jason.infra.local.RunLocalMAS",
                project.getFileName().toString(), "--log-conf", dir.resolve("jason-logging.properties").toString()));
    }

    private static double medianWhole(List<Run> rs) {
        double[] a = rs.stream().mapToDouble(Run::wholeSeconds).sorted().toArray();
        return a[a.length / 2];
    }

    private static Run median(List<Run> rs) {
        Run[] a = rs.toArray(new Run[0]);
        Arrays.sort(a, (x, y) -> Double.compare(x.seconds, y.seconds));
        return a[a.length / 2];
    }

    /** How long a project may run on after its {@code end} line (a program without {@code .stopMAS} never ends). */
    private static final long AFTER_END_MILLIS = 10_000;

    private static void stopAfterEnd(Process p) {
        var stop = new Thread(() -> {
            try {
                if (!p.waitFor(AFTER_END_MILLIS, TimeUnit.MILLISECONDS)) {
                    // the JVM under GNU time, which then reports its peak memory
                    p.descendants().forEach(ProcessHandle::destroyForcibly);
                    if (!p.waitFor(1, TimeUnit.SECONDS)) {
                        p.destroyForcibly();
                    }
                }
            } catch (InterruptedException e) {
                // the benchmark is ending
            }
        });
        stop.setDaemon(true);
        stop.start();
    }

    private Run measure(String who, Path project, List<String> javaArgs) throws IOException, InterruptedException {
        Path timeFile = dir.resolve("time.txt");
        var cmd = new ArrayList<String>();
        boolean gnuTime = Files.isExecutable(Path.of("/usr/bin/time"));
        if (gnuTime) {
            cmd.addAll(List.of("/usr/bin/time", "-f", "%M", "-o", timeFile.toString()));
        }
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Djava.awt.headless=true");
        cmd.addAll(javaArgs);
        long began = System.nanoTime();
        Process p = new ProcessBuilder(cmd).directory(project.getParent().toFile()).redirectErrorStream(true).start();
        var cut = new AtomicBoolean();
        var limit = new Thread(() -> {
            try {
                Thread.sleep((long) (limitSeconds * 1000));
                cut.set(true);
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
            } catch (InterruptedException e) {
                // the run ended in time
            }
        });
        limit.setDaemon(true);
        limit.start();
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
                    stopAfterEnd(p);
                } else if (line.startsWith("cycles ")) {
                    cycles = Long.parseLong(line.substring(7).trim());
                }
            }
        }
        if (!p.waitFor(10, TimeUnit.MINUTES)) {
            p.destroyForcibly();
        }
        double whole = (System.nanoTime() - began) / 1e9;
        limit.interrupt();
        if (cut.get()) {
            return new Run(limitSeconds, whole, 0, cycles, true);
        }
        if (start < 0 || end < 0) {
            throw new IOException(project + ": on " + who + ", no agent printed its `start` and `end` lines"
                    + " (.print(start) and .print(end) around what is measured)");
        }
        long peak = gnuTime ? Long.parseLong(Files.readString(timeFile).trim().lines().reduce((a, b) -> b).orElse("0")) : 0;
        return new Run((end - start) / 1e9, whole, peak, cycles, false);
    }
}
