package jacabot.app.sweep;

import jacabot.app.world.Reachability;
import jacabot.robot.Experiment;
import jacabot.robot.run.RunRecorder;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * What a robot could physically do in a world in {@link SuccessCriteria#NOMINAL_S} whatever its
 * controller, so that the criteria never count a world's impossibility as the controller's failure.
 * Read from the world at start ({@link Reachability}: where the robot's centre can go, and the
 * shortest drives around walls and boxes), for a robot that drives at full speed for
 * {@link #ATTAINABLE} of the run (the rest goes to turning, avoiding, gripping and driving over
 * ground already seen):
 * <ul>
 * <li>{@code coverage}: the share of the arena's coverage cells required, the criteria's 50 % or, when
 *     less, {@link #ATTAINABLE} of what it can enter (cells its centre can reach, at most one new cell
 *     per cell length driven). A 4 m hall for a MyBot at 0.1 m/s: 60 m, 600 cells of 1 600, so 28 %;
 *     an arena of up to 3 m a side keeps 50 %;</li>
 * <li>{@code deliveries}: how many deliveries the shortest tour allows (start, nearest cylinder, storage,
 *     then storage and back for the next nearest), for navigation (on the battery it starts with: its
 *     world has no charger) and suspend/resume;</li>
 * <li>{@code storable} and {@code parkable}: for tidy-up, how many cylinders that tour stores, and
 *     whether the drive to the charger after the last still fits; a tour that needs more energy than
 *     the robot starts with also pays for a visit to the charger on the way and the charge's time.</li>
 * </ul>
 * Cylinders behind a passage narrower than the robot are never asked for: the generator puts none
 * there, and a hand-made world's are left out of the tour (so out of what is required).
 */
public record PhysicalBounds(double coverage, int deliveries, int storable, boolean parkable) {
    /** The share of the run a robot is assumed to drive at full speed into new ground. */
    public static final double ATTAINABLE = 0.75;
    /** No bound: the criteria as written. */
    public static final PhysicalBounds NONE = new PhysicalBounds(SuccessCriteria.MIN_COVERAGE, Integer.MAX_VALUE,
            Integer.MAX_VALUE, true);

    /** {@return the bounds of {@code world} for its first robot} */
    public static PhysicalBounds of(Experiment experiment, WorldSpec world) {
        if (world == null || world.robots().isEmpty()) {
            return NONE;
        }
        RobotSpec r = world.robots().get(0);
        RobotModel model = RobotModel.byName(r.model()).orElse(null);
        if (model == null) {
            return NONE;
        }
        Reachability reach = Reachability.of(world, model.radius(), r.x(), r.z());
        double cell = RunRecorder.CELL_SIZE;
        int cells = Math.max(1, (int) Math.round(world.arena().width() / cell))
                * Math.max(1, (int) Math.round(world.arena().depth() / cell));
        double enterable = Math.min(reach.reachableCells(cell), SuccessCriteria.NOMINAL_S * model.speedUnit() * model.maxSpeed() / cell);
        double coverage = Math.min(SuccessCriteria.MIN_COVERAGE, ATTAINABLE * enterable / cells);
        if (world.storage() == null) {
            return new PhysicalBounds(coverage, Integer.MAX_VALUE, Integer.MAX_VALUE, true);
        }
        double within = model.radius() + 0.03;
        AreaSpec storage = world.storage();
        AreaSpec charger = world.charger();
        Reachability fromStorage = reach.from(storage.x(), storage.z());
        Reachability fromCharger = charger == null ? null : reach.from(charger.x(), charger.z());
        List<double[]> legs = new ArrayList<>(); // per reachable cylinder: start -> it, storage -> it, charger -> it
        for (CylinderSpec c : world.cylinders()) {
            double a = reach.distanceTo(c.x(), c.z(), within), b = fromStorage.distanceTo(c.x(), c.z(), within);
            if (a < Double.POSITIVE_INFINITY && b < Double.POSITIVE_INFINITY) {
                legs.add(new double[] {a, b, fromCharger == null ? Double.POSITIVE_INFINITY : fromCharger.distanceTo(c.x(), c.z(), within)});
            }
        }
        // the first: the cheapest start -> cylinder -> storage; then the nearest to the storage area, there and back
        legs.sort((p, q) -> Double.compare(p[0] + p[1], q[0] + q[1]));
        if (legs.size() > 1) {
            List<double[]> rest = new ArrayList<>(legs.subList(1, legs.size()));
            rest.sort((p, q) -> Double.compare(p[1], q[1]));
            legs = new ArrayList<>(legs.subList(0, 1));
            legs.addAll(rest);
        }
        // tidy-up's task includes the charger; navigation's robot has only the battery it starts with
        boolean battery = experiment == Experiment.TIDY_UP || experiment == Experiment.NAVIGATION;
        Recharge recharge = Recharge.of(experiment == Experiment.TIDY_UP ? world.charger() : null, battery, model, r, reach, fromStorage);
        double toCharger = charger == null ? 0 : fromStorage.distanceTo(charger.x(), charger.z(), charger.radius() / 2);
        double used = 0;
        int delivered = 0;
        double detour = Double.POSITIVE_INFINITY; // the cheapest visit to the charger on the tour so far
        for (int k = 0; k < legs.size(); k++) {
            double[] leg = legs.get(k);
            double more = k == 0 ? leg[0] + leg[1] : 2 * leg[1];
            double d = Math.min(detour, recharge.insertion(leg, k == 0));
            if (used + more > recharge.drive(used + more, d)) {
                break;
            }
            used += more;
            detour = d;
            delivered++;
        }
        boolean parkable = delivered == legs.size() && used + toCharger <= recharge.drive(used + toCharger, detour);
        return new PhysicalBounds(coverage, delivered, delivered, parkable);
    }

    /**
     * The battery's part of a tidy-up tour. A tour that needs more energy than the robot starts with
     * must visit the charger before its end (parking comes too late to help): the cheapest such visit
     * is a detour on one of the tour's legs, and the charge itself takes time at the charger's power.
     * Both come out of the drive the run leaves. Energy: the idle power for the whole run and the
     * motors' power at full speed while driving (the model's battery). Navigation's robot has no
     * charger: a tour that needs more energy than it starts with does not fit (1 000 J: 17.5 m for
     * a Khepera, against the 22.5 m of three quarters of the run). A robot without battery, or
     * suspend/resume and obstacle avoidance, drives as far as the run allows.
     */
    private record Recharge(double drive, double speed, double needBase, double motorPower, double start, double chargerPower,
                            double startToCharger, double storageToCharger) {
        static Recharge of(AreaSpec charger, boolean counted, RobotModel model, RobotSpec r, Reachability reach, Reachability fromStorage) {
            double speed = model.speedUnit() * model.maxSpeed();
            double drive = ATTAINABLE * SuccessCriteria.NOMINAL_S * speed;
            RobotModel.BatteryDef battery = model.battery();
            if (battery == null || !counted) {
                return new Recharge(drive, speed, 0, 0, Double.POSITIVE_INFINITY, 1, 0, 0);
            }
            double start = Double.isNaN(r.battery()) ? battery.maxEnergy() : Math.min(r.battery(), battery.maxEnergy());
            double idle = battery.idlePower() * SuccessCriteria.NOMINAL_S;
            if (charger == null || !(charger.power() > 0)) { // no charge on the way: the tour fits the battery or ends
                return new Recharge(drive, speed, idle, battery.motorPower(), start, 1, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY);
            }
            return new Recharge(drive, speed, idle, battery.motorPower(), start,
                    charger.power(), reach.distanceTo(charger.x(), charger.z(), charger.radius() / 2),
                    fromStorage.distanceTo(charger.x(), charger.z(), charger.radius() / 2));
        }

        /** {@return the extra metres of visiting the charger on a leg (start -> it -> storage for the first, else storage -> it -> storage)} */
        double insertion(double[] leg, boolean first) {
            double out = first ? leg[0] : leg[1];
            double viaOut = (first ? startToCharger : storageToCharger) + leg[2];
            double viaBack = leg[2] + storageToCharger;
            return Math.min(viaOut - out, viaBack - leg[1]);
        }

        /** {@return the drive the run leaves for a tour of {@code metres}, the charger {@code detour} m off it} */
        double drive(double metres, double detour) {
            double need = needBase + motorPower * metres / speed;
            if (need <= start) {
                return drive;
            }
            if (detour == Double.POSITIVE_INFINITY) {
                return 0;
            }
            double charging = (need + motorPower * detour / speed - start) / chargerPower;
            return ATTAINABLE * (SuccessCriteria.NOMINAL_S - charging) * speed - detour;
        }
    }

    /** {@return the bounds as one line, e.g. "physical bound: coverage 28%, 3 deliveries"} */
    public String describe() {
        return String.format(Locale.ROOT, "physical bound: coverage %.0f%%, %s deliveries%s", 100 * coverage,
                deliveries == Integer.MAX_VALUE ? "any" : Integer.toString(deliveries), parkable ? "" : ", no time to park");
    }
}
