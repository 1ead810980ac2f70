package jacabot.app.sweep;

import jacabot.robot.Experiment;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.function.ToDoubleFunction;

/**
 * A sweep's files: {@code runs.csv} (one row per run, what {@code sweep merge} reads back) and
 * {@code report.md} (a table per experiment: successes under {@link SuccessCriteria}, medians, and
 * each failed run with its reason).
 */
public final class SweepReport {
    /** The CSV's columns, in order. */
    public static final List<String> COLUMNS = List.of("experiment", "world", "controller", "seed", "status", "success",
            "simulated_s", "wall_s", "contact_s", "coverage", "picks", "deliveries", "storage_entries_empty", "battery_min",
            "battery_emptied", "low_battery_episodes", "episodes_completed", "lost", "reason");

    private SweepReport() {
    }

    // ---- CSV --------------------------------------------------------------------------------------

    /** {@return the CSV text of the outcomes, header first} */
    public static String csv(List<RunOutcome> runs) {
        StringBuilder b = new StringBuilder(String.join(",", COLUMNS)).append('\n');
        for (RunOutcome o : runs) {
            var f = o.figures();
            List<String> cells = List.of(o.experiment().id(), o.world(), o.controller(), Long.toString(o.seed()), o.status(),
                    Boolean.toString(o.success()), n(o.simulated(), 3), n(o.wall(), 3), n(f.contactTime(), 3), n(f.coverage(), 4),
                    Integer.toString(f.picks()), Integer.toString(f.deliveries()), Integer.toString(f.storageEntriesEmpty()),
                    Double.isNaN(o.batteryMin()) ? "" : n(o.batteryMin(), 1), Boolean.toString(f.batteryEmptied()),
                    Integer.toString(f.lowBatteryEpisodes()), Integer.toString(f.episodesCompleted()), Integer.toString(o.lost()),
                    o.reason());
            for (int i = 0; i < cells.size(); i++) {
                b.append(i == 0 ? "" : ",").append(quote(cells.get(i)));
            }
            b.append('\n');
        }
        return b.toString();
    }

    /** {@return the outcomes of a CSV written by {@link #csv}} @throws IllegalArgumentException naming file and line */
    public static List<RunOutcome> readCsv(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        if (lines.isEmpty() || !split(lines.get(0)).equals(COLUMNS)) {
            throw new IllegalArgumentException(file + ":1: not a sweep CSV (expected the header " + String.join(",", COLUMNS) + ")");
        }
        List<RunOutcome> out = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            if (lines.get(i).isBlank()) {
                continue;
            }
            List<String> c = split(lines.get(i));
            try {
                if (c.size() != COLUMNS.size()) {
                    throw new IllegalArgumentException(c.size() + " columns, expected " + COLUMNS.size());
                }
                Experiment e = Experiment.byId(c.get(0));
                var f = new SuccessCriteria.Figures(Double.parseDouble(c.get(6)), Double.parseDouble(c.get(8)),
                        Double.parseDouble(c.get(9)), Integer.parseInt(c.get(10)), Integer.parseInt(c.get(11)),
                        Integer.parseInt(c.get(12)), Boolean.parseBoolean(c.get(14)), Integer.parseInt(c.get(15)),
                        Integer.parseInt(c.get(16)));
                out.add(new RunOutcome(e, c.get(1), c.get(2), Long.parseLong(c.get(3)), c.get(4), Boolean.parseBoolean(c.get(5)),
                        c.get(18), f.duration(), Double.parseDouble(c.get(7)), f,
                        c.get(13).isEmpty() ? Double.NaN : Double.parseDouble(c.get(13)), Integer.parseInt(c.get(17))));
            } catch (IllegalArgumentException ex) {
                throw new IllegalArgumentException(file + ":" + (i + 1) + ": " + ex.getMessage());
            }
        }
        return out;
    }

    private static String quote(String s) {
        return s.contains(",") || s.contains("\"") || s.contains("\n") ? "\"" + s.replace("\"", "\"\"").replace('\n', ' ') + "\"" : s;
    }

    static List<String> split(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder cell = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char ch = line.charAt(i);
            if (quoted) {
                if (ch == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                    cell.append('"');
                    i++;
                } else if (ch == '"') {
                    quoted = false;
                } else {
                    cell.append(ch);
                }
            } else if (ch == '"') {
                quoted = true;
            } else if (ch == ',') {
                out.add(cell.toString());
                cell.setLength(0);
            } else {
                cell.append(ch);
            }
        }
        out.add(cell.toString());
        return out;
    }

    // ---- Markdown ---------------------------------------------------------------------------------

    /**
     * {@return the Markdown report}
     *
     * @param throughput a line on simulated minutes per wall-clock second, or null
     */
    public static String markdown(List<RunOutcome> unsorted, String throughput) {
        List<RunOutcome> runs = new ArrayList<>(unsorted);
        runs.sort(Sweep.ORDER);
        StringBuilder b = new StringBuilder("# Sweep\n\n");
        b.append(runs.size()).append(" runs. Success criteria: docs/comparison.md, \"Success criteria\".");
        if (throughput != null) {
            b.append(' ').append(throughput);
        }
        b.append("\n");
        double shortest = runs.stream().mapToDouble(o -> o.status().equals(RunOutcome.OK) ? o.simulated() : Double.MAX_VALUE)
                .min().orElse(Double.MAX_VALUE);
        SuccessCriteria.caveat(shortest).ifPresent(c -> b.append("\n**Note:** ").append(c).append(".\n"));
        for (Experiment e : Experiment.values()) {
            List<RunOutcome> mine = runs.stream().filter(o -> o.experiment() == e).toList();
            if (mine.isEmpty()) {
                continue;
            }
            b.append("\n## ").append(e.id()).append("\n\n");
            b.append("| controller | runs | successes | median contact (s) | median coverage | median picks | median deliveries "
                    + "| empty storage entries | low-battery episodes completed | crashes / hangs / early ends / agent failures |\n");
            b.append("|---|---|---|---|---|---|---|---|---|---|\n");
            for (String controller : SweepJob.CONTROLLERS) {
                List<RunOutcome> c = mine.stream().filter(o -> o.controller().equals(controller)).toList();
                if (c.isEmpty()) {
                    continue;
                }
                long ok = c.stream().filter(RunOutcome::success).count();
                int episodes = c.stream().mapToInt(o -> o.figures().lowBatteryEpisodes()).sum();
                int completed = c.stream().mapToInt(o -> o.figures().episodesCompleted()).sum();
                b.append(String.format(Locale.ROOT, "| %s | %d | %d (%.0f%%) | %.1f | %.0f%% | %s | %s | %d | %s | %d / %d / %d / %d |%n",
                        controller, c.size(), ok, 100.0 * ok / c.size(), median(c, o -> o.figures().contactTime()),
                        100 * median(c, o -> o.figures().coverage()), n(median(c, o -> o.figures().picks()), 1),
                        n(median(c, o -> o.figures().deliveries()), 1),
                        c.stream().mapToInt(o -> o.figures().storageEntriesEmpty()).sum(),
                        episodes == 0 ? "-" : completed + " of " + episodes,
                        status(c, RunOutcome.CRASH), status(c, RunOutcome.HANG), status(c, RunOutcome.EARLY_END),
                        status(c, RunOutcome.AGENT_FAILURE)));
            }
            List<RunOutcome> failed = mine.stream().filter(o -> !o.success()).toList();
            if (!failed.isEmpty()) {
                b.append("\nFailed runs:\n\n");
                for (RunOutcome o : failed) {
                    b.append("- ").append(o.controller()).append(", ").append(o.world()).append(", seed ").append(o.seed())
                            .append(": ").append(o.reason()).append('\n');
                }
            }
        }
        return b.toString();
    }

    private static long status(List<RunOutcome> runs, String status) {
        return runs.stream().filter(o -> o.status().equals(status)).count();
    }

    private static double median(List<RunOutcome> runs, ToDoubleFunction<RunOutcome> f) {
        double[] v = runs.stream().mapToDouble(f).sorted().toArray();
        if (v.length == 0) {
            return Double.NaN;
        }
        return v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
    }

    private static String n(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        if (s.contains(".")) {
            s = s.replaceAll("0+$", "").replaceAll("\\.$", "");
        }
        return s;
    }

    /** {@return the outcomes of several CSVs joined, in report order, without repeated runs} */
    public static List<RunOutcome> merge(List<List<RunOutcome>> parts) {
        List<RunOutcome> all = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        for (List<RunOutcome> p : parts) {
            for (RunOutcome o : p) {
                if (seen.add(String.join("\u0000", Arrays.asList(o.experiment().id(), o.world(), o.controller(),
                        Long.toString(o.seed()))))) {
                    all.add(o);
                }
            }
        }
        all.sort(Sweep.ORDER);
        return all;
    }
}
