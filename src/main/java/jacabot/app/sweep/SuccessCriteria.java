package jacabot.app.sweep;

import jacabot.robot.Experiment;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * Whether a run did its experiment's task on worlds nobody tuned it for (docs/comparison.md,
 * "Success criteria"), the one definition the sweep and the scenario tests share. Made for runs of
 * {@link #NOMINAL_S} = 10 simulated minutes:
 * <ul>
 * <li>obstacle avoidance: contact under {@link #MAX_CONTACT_S} s in all and coverage at least
 *     {@link #MIN_COVERAGE} (10 cm cells);</li>
 * <li>object picking: at least one cylinder picked;</li>
 * <li>navigation: at least {@link #MIN_DELIVERIES} deliveries, never into the storage area without a cylinder;</li>
 * <li>suspend/resume: the battery never empty, at least one delivery, and every low-battery episode
 *     ({@link BatteryEpisodes}) recharged and returned from, except one begun in the last
 *     {@link #EPISODE_GRACE_S} s of the run (it has not had the time);</li>
 * <li>tidy-up (not in the thesis): the battery never empty, and at the end every cylinder of the world
 *     lies in the storage area (its centre within the area's radius) and the robot is parked on the
 *     charger (its centre within the charger's radius).</li>
 * </ul>
 * A run that crashed, hung or ended early fails whatever its figures. The sweep judges every run
 * against its world's {@link PhysicalBounds} (what a robot could do there at all): nothing changes
 * in arenas of up to 3 m a side with every cylinder reachable; in larger ones the coverage required
 * falls to what the robot can drive over, and a delivery tour longer than the run asks for fewer.
 *
 * <p>Other durations: what is a rate scales with the run's duration (the deliveries, at least one;
 * the contact allowed, never below 2 s); coverage, a first pick or delivery and a recharge do not
 * grow in proportion to time, so a run shorter than 10 minutes is judged by them as they are, and
 * {@link #caveat} says so (the sweep warns and marks its report).
 *
 * <p>A team's run (team-delivery, thesis Chapter 6), {@link #judgeTeam}: deliveries counted for the
 * team, at least {@link #MIN_DELIVERIES} per robot (no more than the world's cylinders); every
 * robot's contact with another robot under {@link #MAX_CONTACT_S} s (contact with walls and boxes
 * is a robot's own affair, judged by the one-robot experiments) and its battery never empty; no
 * cylinder ever claimed by two robots at once; no robot waiting for the charger longer than
 * {@link #MAX_CHARGER_WAIT_S} s. Across runs, a team of N should deliver {@link #scalingTarget}
 * times what one robot delivers on the same worlds and seeds.
 */
public final class SuccessCriteria {
    public static final double MAX_CONTACT_S = 2.0;
    public static final double MIN_COVERAGE = 0.5;
    public static final int MIN_DELIVERIES = 2;
    public static final double EPISODE_GRACE_S = 180;
    /** The duration the criteria are made for, simulated seconds. */
    public static final double NOMINAL_S = 600;
    /** The longest a robot of a team may wait for the charger, seconds (from asking to holding it). */
    public static final double MAX_CHARGER_WAIT_S = 60;

    private SuccessCriteria() {
    }

    /**
     * What the criteria read from a run; {@code cylinders}, {@code stored} and {@code parked} are the
     * end of the run (how many cylinders the world has, how many lie in the storage area, whether the
     * robot is on the charger), read for tidy-up only.
     */
    public record Figures(double duration, double contactTime, double coverage, int picks, int deliveries,
                          int storageEntriesEmpty, boolean batteryEmptied, int lowBatteryEpisodes, int episodesCompleted,
                          int cylinders, int stored, boolean parked) {
        /** The figures of an experiment of the thesis (no end state read). */
        public Figures(double duration, double contactTime, double coverage, int picks, int deliveries,
                int storageEntriesEmpty, boolean batteryEmptied, int lowBatteryEpisodes, int episodesCompleted) {
            this(duration, contactTime, coverage, picks, deliveries, storageEntriesEmpty, batteryEmptied, lowBatteryEpisodes,
                    episodesCompleted, 0, 0, false);
        }
    }

    /**
     * What the team criteria read from a run.
     *
     * @param contactTimes        each robot's contact time (walls, boxes, robots), seconds, in the world file's order
     * @param robotContactTimes   each robot's time touching another robot, seconds, in the same order
     * @param batteriesEmptied    how many robots' batteries ran empty
     * @param doubleClaims        how many times a cylinder was claimed by a second robot while claimed
     * @param longestChargerWait  the longest a robot waited for the charger, seconds
     */
    public record TeamFigures(double duration, int cylinders, int deliveries, List<Double> contactTimes,
                              List<Double> robotContactTimes, int batteriesEmptied, int doubleClaims, double longestChargerWait) {
        public TeamFigures {
            contactTimes = List.copyOf(contactTimes);
            robotContactTimes = List.copyOf(robotContactTimes);
            if (robotContactTimes.size() != contactTimes.size()) {
                throw new IllegalArgumentException("a contact time and a robot contact time per robot");
            }
        }

        /** {@return the longest any robot of the team touched another robot, seconds} */
        public double maxRobotContact() {
            return robotContactTimes.stream().mapToDouble(Double::doubleValue).max().orElse(0);
        }

        /** {@return the team's size} */
        public int robots() {
            return contactTimes.size();
        }
    }

    /** The verdict: success, or the reasons it failed (semicolon-separated in reports). */
    public record Verdict(boolean success, List<String> reasons) {
        public Verdict {
            reasons = List.copyOf(reasons);
        }

        /** {@return the reasons as one line, "" on success} */
        public String reason() {
            return String.join("; ", reasons);
        }
    }

    /** {@return how many low-battery episodes must be complete: all but one begun in the last grace period} */
    public static int episodesDue(List<BatteryEpisodes.Episode> episodes, double duration) {
        int due = 0;
        for (BatteryEpisodes.Episode e : episodes) {
            if (e.completed() || e.lowAt() < duration - EPISODE_GRACE_S) {
                due++;
            }
        }
        return due;
    }

    /** {@return the deliveries a navigation run of {@code seconds} must make: 2 per 10 minutes, at least 1} */
    public static int minDeliveries(double seconds) {
        return Math.max(1, (int) Math.ceil(MIN_DELIVERIES * seconds / NOMINAL_S - 1e-9));
    }

    /** {@return the contact allowed in a run of {@code seconds}: 2 s per 10 minutes, never less than 2 s} */
    public static double maxContact(double seconds) {
        return Math.max(MAX_CONTACT_S, MAX_CONTACT_S * seconds / NOMINAL_S);
    }

    /** {@return for runs shorter than the criteria were made for, what that means for their verdicts} */
    public static Optional<String> caveat(double seconds) {
        if (seconds >= NOMINAL_S - 1e-9) {
            return Optional.empty();
        }
        return Optional.of(String.format(Locale.ROOT, "runs of %.0f s are judged by criteria made for 10 simulated minutes: "
                + "deliveries and contact scale with the duration, but coverage (50%%), a first pick, a first delivery and "
                + "a recharge do not, so a run this short may fail for want of time (docs/comparison.md, \"Success criteria\")",
                seconds));
    }

    /** {@return the verdict on a run's figures, by the criteria as written} */
    public static Verdict judge(Experiment experiment, Figures f) {
        return judge(experiment, f, PhysicalBounds.NONE);
    }

    /**
     * {@return the verdict on a run's figures, asking no more than the world physically allows}: the
     * coverage required is the bound's when lower, the deliveries and the cylinders stored at most the
     * bound's, and parking only when the tour leaves time for it ({@link PhysicalBounds})
     */
    public static Verdict judge(Experiment experiment, Figures f, PhysicalBounds b) {
        List<String> why = new ArrayList<>();
        switch (experiment) {
            case OBSTACLE_AVOIDANCE -> {
                if (!(f.contactTime() < maxContact(f.duration()))) {
                    why.add(fmt("contact %.1f s (>= %.0f s)", f.contactTime(), maxContact(f.duration())));
                }
                double required = Math.min(MIN_COVERAGE, b.coverage());
                if (!(f.coverage() >= required - 1e-9)) {
                    why.add(fmt("coverage %.0f%% (< %.0f%%%s)", 100 * f.coverage(), 100 * required,
                            required < MIN_COVERAGE ? ", the physical bound" : ""));
                }
            }
            case OBJECT_PICKING -> {
                if (f.picks() < 1) {
                    why.add("no cylinder picked");
                }
            }
            case NAVIGATION -> {
                int due = Math.min(minDeliveries(f.duration()), b.deliveries());
                if (f.deliveries() < due) {
                    why.add(f.deliveries() + " deliver" + (f.deliveries() == 1 ? "y" : "ies") + " (< " + due + ")");
                }
                if (f.storageEntriesEmpty() > 0) {
                    why.add(f.storageEntriesEmpty() + " storage entr" + (f.storageEntriesEmpty() == 1 ? "y" : "ies")
                            + " without a cylinder");
                }
            }
            case SUSPEND_RESUME -> {
                if (f.batteryEmptied()) {
                    why.add("battery empty");
                }
                if (f.deliveries() < Math.min(1, b.deliveries())) {
                    why.add("no delivery");
                }
                if (f.episodesCompleted() < f.lowBatteryEpisodes()) {
                    why.add((f.lowBatteryEpisodes() - f.episodesCompleted()) + " of " + f.lowBatteryEpisodes()
                            + " low-battery episodes without recharge and return");
                }
            }
            case TIDY_UP -> {
                if (f.batteryEmptied()) {
                    why.add("battery empty");
                }
                int due = Math.min(f.cylinders(), b.storable());
                if (f.stored() < due) {
                    why.add(f.stored() + " of " + f.cylinders() + " cylinders in the storage area"
                            + (due < f.cylinders() ? " (< " + due + ", the physical bound)" : ""));
                }
                if (!f.parked() && b.parkable()) {
                    why.add("not parked on the charger");
                }
            }
            default -> throw new IllegalArgumentException("no criteria for " + experiment);
        }
        return new Verdict(why.isEmpty(), why);
    }

    /** {@return the verdict on a team's run} */
    public static Verdict judgeTeam(TeamFigures f) {
        List<String> why = new ArrayList<>();
        int due = Math.min(MIN_DELIVERIES * f.robots(), f.cylinders());
        if (f.deliveries() < due) {
            why.add(f.deliveries() + " team deliver" + (f.deliveries() == 1 ? "y" : "ies") + " (< " + due + ")");
        }
        for (int i = 0; i < f.robots(); i++) {
            if (!(f.robotContactTimes().get(i) < MAX_CONTACT_S)) {
                why.add(fmt("robot %d: contact with robots %.1f s (>= %.0f s)", i + 1, f.robotContactTimes().get(i), MAX_CONTACT_S));
            }
        }
        if (f.batteriesEmptied() > 0) {
            why.add(f.batteriesEmptied() + (f.batteriesEmptied() == 1 ? " battery" : " batteries") + " empty");
        }
        if (f.doubleClaims() > 0) {
            why.add(f.doubleClaims() + " double claim" + (f.doubleClaims() == 1 ? "" : "s"));
        }
        if (f.longestChargerWait() > MAX_CHARGER_WAIT_S) {
            why.add(fmt("waited %.0f s for the charger (> %.0f s)", f.longestChargerWait(), MAX_CHARGER_WAIT_S));
        }
        return new Verdict(why.isEmpty(), why);
    }

    /**
     * {@return how many times one robot's deliveries a team of {@code robots} should deliver, on the
     * same worlds and seeds: 1.7 for two, 3 for four (0.85 and 0.75 of linear: robots get in each
     * other's way and share one charger); other sizes interpolate 0.85 to 0.75 of linear}
     */
    public static double scalingTarget(int robots) {
        if (robots < 1) {
            throw new IllegalArgumentException("a team has at least one robot, got " + robots);
        }
        if (robots == 1) {
            return 1;
        }
        double efficiency = robots >= 4 ? 0.75 : 0.85 - (robots - 2) * 0.05;
        return robots * efficiency;
    }

    private static String fmt(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }
}
