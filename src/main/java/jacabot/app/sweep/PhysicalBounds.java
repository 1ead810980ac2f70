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
 *     then storage and back for the next nearest), for navigation and suspend/resume;</li>
 * <li>{@code storable} and {@code parkable}: for tidy-up, how many cylinders that tour stores, and
 *     whether the drive to the charger after the last still fits (recharging time not counted).</li>
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
        double drive = ATTAINABLE * SuccessCriteria.NOMINAL_S * model.speedUnit() * model.maxSpeed();
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
        Reachability fromStorage = reach.from(storage.x(), storage.z());
        List<double[]> legs = new ArrayList<>(); // per reachable cylinder: start -> it, storage -> it
        for (CylinderSpec c : world.cylinders()) {
            double a = reach.distanceTo(c.x(), c.z(), within), b = fromStorage.distanceTo(c.x(), c.z(), within);
            if (a < Double.POSITIVE_INFINITY && b < Double.POSITIVE_INFINITY) {
                legs.add(new double[] {a, b});
            }
        }
        // the first: the cheapest start -> cylinder -> storage; then the nearest to the storage area, there and back
        legs.sort((p, q) -> Double.compare(p[0] + p[1], q[0] + q[1]));
        double used = 0;
        int delivered = 0;
        if (!legs.isEmpty() && legs.get(0)[0] + legs.get(0)[1] <= drive) {
            used = legs.get(0)[0] + legs.get(0)[1];
            delivered = 1;
            List<double[]> rest = new ArrayList<>(legs.subList(1, legs.size()));
            rest.sort((p, q) -> Double.compare(p[1], q[1]));
            for (double[] leg : rest) {
                if (used + 2 * leg[1] > drive) {
                    break;
                }
                used += 2 * leg[1];
                delivered++;
            }
        }
        AreaSpec charger = world.charger();
        double toCharger = charger == null ? 0 : fromStorage.distanceTo(charger.x(), charger.z(), charger.radius() / 2);
        boolean parkable = delivered == legs.size() && used + toCharger <= drive;
        return new PhysicalBounds(coverage, delivered, delivered, parkable);
    }

    /** {@return the bounds as one line, e.g. "physical bound: coverage 28%, 3 deliveries"} */
    public String describe() {
        return String.format(Locale.ROOT, "physical bound: coverage %.0f%%, %s deliveries%s", 100 * coverage,
                deliveries == Integer.MAX_VALUE ? "any" : Integer.toString(deliveries), parkable ? "" : ", no time to park");
    }
}
