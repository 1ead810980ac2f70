package jacabot.app.plot;

import jacabot.app.inspector.MindState;
import jacabot.app.replay.StepLog;
import jacabot.app.replay.TeamRuns;
import jacabot.sim.engine.WorldSnapshot;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.function.Consumer;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The run's plots, as PNG next to {@code trajectory.png} (XChart): battery over time with the
 * agent's low-battery reactions, the recharges and the resumes; speed and wheel commands; the
 * trajectory with its events; histograms of the reactive and response times. Read from the
 * run's folder ({@value StepLog#FILE}, {@code event-log.txt}, {@value #LATENCY}), so
 * {@code jacabot plot runs/X} redraws them.
 *
 * <p>Which agent events count as low battery, resume or mark is read from the names in its
 * plans' triggers (battery, charg, resum/restor, mark), as the thesis' agents name them.
 */
public final class RunPlots {
    /** Reactive and response times of the run, one {@code kind,microseconds} per line. */
    public static final String LATENCY = "latency.csv";
    public static final List<String> FILES = List.of("battery.png", "speed.png", "events.png", "latency.png");
    /** The charts' width in pixels; the time series are thinned to their envelope at this many columns. */
    private static final int WIDTH = 900;

    private static final Pattern EVENT = Pattern.compile("t=([0-9.]+) (.*)");
    /** The mark action, with or without arguments or a namespace ({@code mark}, {@code mark(P)}, {@code .mw::mark}). */
    static final Pattern MARK_ACTION = Pattern.compile("(\\S*::)?mark(\\(.*\\))?");

    private RunPlots() {
    }

    /** A moment of the run worth a mark. */
    record Mark(double t, String kind, String text) {
    }

    /** Writes the latency samples of a run (microseconds) for {@link #writeAll}. */
    public static void writeLatency(Path outDir, long[] reactive, long[] response) throws IOException {
        var sb = new StringBuilder("kind,micros\n");
        for (long v : reactive) {
            sb.append("reactive,").append(v).append('\n');
        }
        for (long v : response) {
            sb.append("response,").append(v).append('\n');
        }
        Files.writeString(outDir.resolve(LATENCY), sb);
    }

    /** Draws every plot the folder has data for; prints one line naming them. */
    public static void writeAll(Path outDir, PrintStream out) throws IOException {
        writeAll(outDir, out, null);
    }

    /**
     * As {@link #writeAll(Path, PrintStream)}, the step log's series taken from {@code collected}
     * (filled during the run from the step log's writer, {@link StepLog.Writer#onStep}) instead of
     * read back from the file; null: read the file.
     */
    public static void writeAll(Path outDir, PrintStream out, Series collected) throws IOException {
        var written = new ArrayList<String>();
        Path steps = outDir.resolve(StepLog.FILE);
        if (collected != null || Files.isRegularFile(steps)) {
            var series = collected != null ? collected : Series.read(steps);
            var marks = marks(outDir, series);
            battery(series, marks).ifPresent(c -> save(c, outDir, "battery", written));
            save(speed(series), outDir, "speed", written);
            ImageIO.write(events(series, marks, outDir.getFileName() + ""), "png",
                    outDir.resolve("events.png").toFile());
            written.add("events.png");
        }
        Path latency = outDir.resolve(LATENCY);
        if (Files.isRegularFile(latency)) {
            save(latency(latency), outDir, "latency", written);
        }
        if (!written.isEmpty()) {
            out.println("Plots: " + String.join(", ", written) + " in " + outDir);
        }
    }

    /**
     * A team's folder: each robot's plots in its folder, and every robot's trajectory, each in its
     * colour, in the team's {@code trajectory.png}.
     */
    public static void writeTeam(Path teamDir, PrintStream out) throws IOException {
        List<Path> robots = TeamRuns.robotDirs(teamDir);
        if (robots.isEmpty()) {
            return;
        }
        for (Path r : robots) {
            writeAll(r, out);
        }
        overlay(robots, teamDir.resolve("trajectory.png"));
        out.println("Team trajectories: " + teamDir.resolve("trajectory.png"));
    }

    private static void save(Chart<?, ?> chart, Path dir, String name, List<String> written) {
        try {
            BitmapEncoder.saveBitmap(chart, dir.resolve(name + ".png").toString(), BitmapEncoder.BitmapFormat.PNG);
            written.add(name + ".png");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * The step log as columns: read back from the file, or collected step by step as the step
     * log's writer writes them (the same steps, so the same columns).
     */
    public static final class Series implements Consumer<StepLog.Step> {
        // a step's values in primitive columns (56 bytes a step): a long run keeps no boxed copy of its steps
        final Column t = new Column();
        final Column x = new Column();
        final Column z = new Column();
        final Column battery = new Column();
        final Column left = new Column();
        final Column right = new Column();
        final Column speed = new Column();
        /** The plan selections worth a mark (failures, low battery, resumes), not every selection of the run. */
        final List<Mark> selectionMarks = new ArrayList<>();
        /** Times (s) at which an intention was about to run the {@code mark} action. */
        final List<Double> markActions = new ArrayList<>();
        final WorldSnapshot start;
        final double width;
        final double depth;
        private double px = Double.NaN;
        private double pz = Double.NaN;
        private double pt;

        /** An empty series for the step log that starts with {@code header}. */
        public Series(StepLog.Header header) {
            start = header.start();
            width = header.start().arena().width();
            depth = header.start().arena().depth();
        }

        static Series read(Path file) throws IOException {
            try (var in = new StepLog.Reader(file)) {
                var s = new Series(in.header());
                StepLog.Step step;
                while ((step = in.next()) != null) {
                    s.accept(step);
                }
                return s;
            }
        }

        /** Adds one step (on the step log's writer thread during a run: read it after the log closes). */
        @Override
        public void accept(StepLog.Step step) {
            double now = step.timeMs() / 1000.0;
            var b = step.body();
            t.add(now);
            x.add(b.x());
            z.add(b.z());
            battery.add(b.battery() == null ? Double.NaN : b.battery());
            left.add(b.left());
            right.add(b.right());
            speed.add(Double.isNaN(px) || now <= pt ? 0 : Math.hypot(b.x() - px, b.z() - pz) / (now - pt) * 1000);
            px = b.x();
            pz = b.z();
            pt = now;
            if (step.mind() != null && step.mind().selections() != null) {
                for (MindState.Selection sel : step.mind().selections()) {
                    String kind = selectionKind(sel.event());
                    if (kind != null) {
                        selectionMarks.add(new Mark(sel.timeMs() / 1000.0, kind, sel.event()));
                    }
                }
            }
            if (step.mind() != null && step.mind().intentions() != null && aboutToMark(step.mind().intentions())) {
                markActions.add(now);
            }
        }

        /** The {@code mark} action about to run on top of an intention (the thesis' agent marks its position). */
        private static boolean aboutToMark(List<MindState.IntentionView> intentions) {
            for (MindState.IntentionView i : intentions) {
                if (!i.stack().isEmpty() && MARK_ACTION.matcher(i.stack().get(0).current()).matches()) {
                    return true;
                }
            }
            return false;
        }

        /** The trajectory as {x, z} points. */
        List<double[]> points() {
            var out = new ArrayList<double[]>(x.size());
            for (int i = 0; i < x.size(); i++) {
                out.add(new double[] {x.get(i), z.get(i)});
            }
            return out;
        }

        /** {@return how many steps} */
        int size() {
            return t.size();
        }

        int indexAt(double time) {
            int lo = 0, hi = t.size() - 1;
            while (lo < hi) {
                int mid = (lo + hi) / 2;
                if (t.get(mid) < time) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            return Math.max(0, lo);
        }
    }

    /** The run's events (world and recorder) and the agent's reactions worth a mark. */
    static List<Mark> marks(Path outDir, Series s) throws IOException {
        var out = new ArrayList<Mark>();
        Path log = outDir.resolve("event-log.txt");
        if (Files.isRegularFile(log)) {
            for (String line : Files.readAllLines(log)) {
                Matcher m = EVENT.matcher(line);
                if (!m.matches()) {
                    continue;
                }
                double t = Double.parseDouble(m.group(1));
                String what = m.group(2);
                String kind = what.startsWith("picked") ? "pick"
                        : what.contains("deliver") ? "delivery"
                        : what.startsWith("contact") ? "obstacle"
                        : what.startsWith("reached charger") ? "recharge"
                        : what.startsWith("left charger") ? "charged"
                        : what.startsWith("world:") ? "world" : null;
                if (kind != null) {
                    out.add(new Mark(t, kind, what));
                }
            }
        }
        for (double t : s.markActions) {
            out.add(new Mark(t, "mark", "mark"));
        }
        out.addAll(s.selectionMarks);
        return out;
    }

    /** {@return the mark a plan selected for {@code event} earns (failure, low battery, resume), or null} */
    static String selectionKind(String event) {
        String head = event.toLowerCase(Locale.ROOT).replaceAll("[\\[(].*", "");
        return head.startsWith("-!") ? "failure"
                : head.contains("battery") ? "low battery"
                : head.startsWith("-charg") || head.contains("resum") || head.contains("restor") ? "resume" : null;
    }

    /** A growing column of doubles, one per step. */
    static final class Column {
        private double[] values = new double[1024];
        private int size;

        void add(double v) {
            if (size == values.length) {
                values = Arrays.copyOf(values, size * 2);
            }
            values[size++] = v;
        }

        double get(int i) {
            return values[i];
        }

        int size() {
            return size;
        }

        /** {@return a copy of the values, as the charts take them} */
        double[] values() {
            return Arrays.copyOf(values, size);
        }

        boolean allNaN() {
            for (int i = 0; i < size; i++) {
                if (!Double.isNaN(values[i])) {
                    return false;
                }
            }
            return true;
        }
    }

    static Optional<XYChart> battery(Series s, List<Mark> marks) {
        if (s.battery.allNaN()) {
            return Optional.empty();
        }
        XYChart c = new XYChartBuilder().width(WIDTH).height(420).title("Battery").xAxisTitle("simulated time (s)")
                .yAxisTitle("energy (J)").build();
        Envelope battery = Envelope.of(s.t.values(), s.battery.values(), WIDTH);
        c.addSeries("battery", battery.x(), battery.y()).setMarker(SeriesMarkers.NONE).setLineColor(new Color(40, 110, 60));
        for (String kind : List.of("low battery", "recharge", "charged", "resume", "mark")) {
            var xs = new ArrayList<Double>();
            var ys = new ArrayList<Double>();
            for (Mark m : marks) {
                if (m.kind().equals(kind)) {
                    xs.add(m.t());
                    ys.add(s.battery.get(s.indexAt(m.t())));
                }
            }
            if (!xs.isEmpty()) {
                c.addSeries(kind, xs, ys).setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            }
        }
        c.getStyler().setMarkerSize(10);
        return Optional.of(c);
    }

    static XYChart speed(Series s) {
        XYChart c = new XYChartBuilder().width(WIDTH).height(420).title("Speed and wheel commands")
                .xAxisTitle("simulated time (s)").yAxisTitle("wheel speed (units) / robot speed (mm/s)").build();
        double[] t = s.t.values();
        for (var series : List.of(Map.entry("left wheel", s.left), Map.entry("right wheel", s.right),
                Map.entry("robot speed (mm/s)", s.speed))) {
            Envelope e = Envelope.of(t, series.getValue().values(), WIDTH);
            c.addSeries(series.getKey(), e.x(), e.y()).setMarker(SeriesMarkers.NONE);
        }
        return c;
    }

    /** The trajectory and the marks over the world's geometry, in the renderer's orientation (x right, z down). */
    static BufferedImage events(Series s, List<Mark> marks, String name) {
        var spots = new ArrayList<MapPlot.Spot>();
        for (Mark m : marks) {
            int i = s.indexAt(m.t());
            if (i < s.x.size()) {
                spots.add(new MapPlot.Spot(m.kind(), s.x.get(i), s.z.get(i)));
            }
        }
        return MapPlot.draw(s.start, List.of(new MapPlot.Track(name, s.points())), spots, "trajectory and events", 700);
    }

    /** Overlays several runs' trajectories over the first one's world: {@code jacabot plot RUN_A RUN_B}. */
    public static void overlay(List<Path> runs, Path png) throws IOException {
        var tracks = new ArrayList<MapPlot.Track>();
        WorldSnapshot start = null;
        for (Path run : runs) {
            Series s = Series.read(run.resolve(StepLog.FILE));
            start = start == null ? s.start : start;
            tracks.add(new MapPlot.Track(run.getFileName().toString(), s.points()));
        }
        ImageIO.write(MapPlot.draw(start, tracks, List.of(), "trajectories", 700), "png", png.toFile());
    }

    static CategoryChart latency(Path csv) throws IOException {
        var reactive = new ArrayList<Long>();
        var response = new ArrayList<Long>();
        for (String line : Files.readAllLines(csv)) {
            String[] f = line.split(",");
            if (f.length == 2 && f[1].matches("\\d+")) {
                (f[0].equals("reactive") ? reactive : response).add(Long.parseLong(f[1]));
            }
        }
        // log-spaced bins in microseconds: 1 us .. 100 ms
        double[] edges = new double[16];
        for (int i = 0; i < edges.length; i++) {
            edges[i] = Math.pow(10, i / 3.0);
        }
        var labels = new ArrayList<String>();
        for (int i = 0; i < edges.length - 1; i++) {
            labels.add(label(edges[i]));
        }
        CategoryChart c = new CategoryChartBuilder().width(WIDTH).height(420)
                .title("Reactive and response times (wall clock, " + reactive.size() + " / " + response.size() + " samples)")
                .xAxisTitle("from (us)").yAxisTitle("samples").build();
        c.getStyler().setOverlapped(false);
        c.addSeries("reactive", labels, bins(reactive, edges));
        c.addSeries("response", labels, bins(response, edges));
        return c;
    }

    private static String label(double us) {
        return us < 1000 ? String.format(Locale.ROOT, "%.0f", us) : String.format(Locale.ROOT, "%.0fk", us / 1000);
    }

    private static List<Integer> bins(List<Long> values, double[] edges) {
        var out = new ArrayList<Integer>();
        for (int i = 0; i < edges.length - 1; i++) {
            out.add(0);
        }
        for (long v : values) {
            int i = 0;
            while (i < edges.length - 2 && v >= edges[i + 1]) {
                i++;
            }
            out.set(i, out.get(i) + 1);
        }
        return out;
    }
}
