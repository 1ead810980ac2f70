package jacabot.app.replay;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The longest stretch of a recorded run in which the robot made no progress (the success criteria's "no stretch
 * of more than 30 s in which the robot neither gains coverage nor progresses towards its current
 * target"). Progress is entering a coverage cell not entered before, or coming {@link #CLOSER} m
 * nearer than ever to the current target. The target is what the agent last came to believe as
 * {@code targetPoint(X, Z)} (the storage point, the charger, the marked point) or
 * {@code waypoint(X, Z, _)} (the sweep), and the target point again once the sweep's waypoint is
 * dropped: beliefs of the Khepera agents, read from the step log's mind changes. A run without
 * them is judged by coverage alone. A key step of the log lists the whole mind: a target in it is new
 * only when it was not believed at the step before.
 */
public final class ProgressStretch {
    /** How much nearer than ever before the robot must come to its target, metres. */
    public static final double CLOSER = 0.02;
    private static final Pattern TARGET = Pattern.compile(
            "(targetPoint|waypoint)\\((-?[0-9.]+(?:E-?[0-9]+)?),(-?[0-9.]+(?:E-?[0-9]+)?)[,)].*");

    /** A stretch without progress, simulated seconds. */
    public record Stretch(double fromS, double toS) {
        public double seconds() {
            return toS - fromS;
        }
    }

    private ProgressStretch() {
    }

    /** {@return the longest stretch without progress in the step log {@code file}, with coverage cells of {@code cell} m} */
    public static Stretch longest(Path file, double cell) throws IOException {
        Set<Long> cells = new HashSet<>();
        Set<Target> believed = new LinkedHashSet<>();
        double[] point = null, target = null;
        double nearest = Double.POSITIVE_INFINITY;
        double last = 0, t = 0;
        Stretch worst = new Stretch(0, 0);
        try (var reader = new StepLog.Reader(file)) {
            for (StepLog.Step s = reader.next(); s != null; s = reader.next()) {
                t = s.timeMs() / 1000.0;
                if (s.mind() != null) {
                    List<Target> added = new ArrayList<>(), removed = new ArrayList<>();
                    if (s.mind().added() != null) {
                        for (var b : s.mind().added()) {
                            addTarget(b.literal(), added);
                        }
                    }
                    if (s.key()) { // the whole mind: only what was not believed before is new
                        removed.addAll(believed);
                        removed.removeAll(added);
                        var snapshot = new LinkedHashSet<>(added);
                        added.removeAll(believed);
                        believed = snapshot;
                    } else {
                        if (s.mind().removed() != null) {
                            for (String b : s.mind().removed()) {
                                addTarget(b, removed);
                            }
                        }
                        believed.removeAll(removed);
                        believed.addAll(added);
                    }
                    for (Target b : removed) {
                        if (b.kind().equals("waypoint") && target != point) {
                            target = point;
                            nearest = Double.POSITIVE_INFINITY;
                        }
                    }
                    for (Target b : added) {
                        target = new double[] {b.x(), b.z()};
                        nearest = Double.POSITIVE_INFINITY;
                        if (b.kind().equals("targetPoint")) {
                            point = target;
                        }
                    }
                }
                double x = s.body().x(), z = s.body().z();
                boolean progress = cells.add((long) Math.floor(x / cell) << 32 ^ ((long) Math.floor(z / cell) & 0xFFFFFFFFL));
                if (target != null) {
                    double d = Math.hypot(x - target[0], z - target[1]);
                    if (d < nearest - CLOSER) {
                        nearest = d;
                        progress = true;
                    }
                }
                if (progress) {
                    if (t - last > worst.seconds()) {
                        worst = new Stretch(last, t);
                    }
                    last = t;
                }
            }
        }
        return t - last > worst.seconds() ? new Stretch(last, t) : worst;
    }

    /** A target belief: its functor ({@code targetPoint} or {@code waypoint}) and its point. */
    private record Target(String kind, double x, double z) {
    }

    /** Adds {@code literal}, when it is a target belief, to {@code targets}. */
    private static void addTarget(String literal, List<Target> targets) {
        Matcher m = TARGET.matcher(literal);
        if (m.matches()) {
            targets.add(new Target(m.group(1), Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3))));
        }
    }
}
