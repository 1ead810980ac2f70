package jacabot.app.sweep;

import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.geom.Vec2;
import jacabot.sim.robot.Robot;
import jacabot.sim.world.AreaSpec;
import java.util.ArrayList;
import java.util.List;

/**
 * Low-battery episodes of one robot, from ground truth (Chapter 4 §4): an episode begins when the
 * energy falls under {@link #LOW} (the thesis' {@code battery < 480 & battery > 0}); it is
 * <em>recharged</em> once the robot has been on the charger and the energy is back to
 * {@link #RECHARGED}; it is <em>completed</em> when, after that, the robot's centre comes back
 * within {@link #RETURN_RADIUS} of where it was when the battery ran low (Appendix B's mark).
 * Listener calls come from the stepping thread; read after the run.
 */
public final class BatteryEpisodes implements WorldListener {
    /** The low-battery threshold, joules (the thesis' 480). */
    public static final double LOW = 480;
    /** Energy that counts as recharged, joules (both controllers charge to 900). */
    public static final double RECHARGED = 800;
    /** How near the low-battery position the robot must come back, metres (the controllers aim at 3-6 cm). */
    public static final double RETURN_RADIUS = 0.15;

    /** One episode: times in simulated seconds, NaN while it has not happened. */
    public record Episode(double lowAt, Vec2 mark, double rechargedAt, double returnedAt) {
        public boolean completed() {
            return !Double.isNaN(returnedAt);
        }
    }

    private final Robot robot;
    private final AreaSpec charger;
    private final List<Episode> episodes = new ArrayList<>();
    private double lowAt = Double.NaN, rechargedAt = Double.NaN;
    private Vec2 mark;
    private boolean charged;

    private BatteryEpisodes(SimWorld world, String robotName) {
        this.robot = world.robot(robotName);
        this.charger = world.spec().charger();
    }

    /** {@return episodes of a robot, listening from now on; a robot without battery has none} */
    public static BatteryEpisodes attach(SimWorld world, String robotName) {
        BatteryEpisodes b;
        synchronized (world) {
            b = new BatteryEpisodes(world, robotName);
        }
        world.addListener(b);
        return b;
    }

    @Override
    public void controlStepEnded(long timeMs) {
        if (!robot.hasBattery()) {
            return;
        }
        double e = robot.getBattery().energy();
        double t = timeMs / 1000.0;
        Vec2 at = robot.pose().position();
        if (Double.isNaN(lowAt)) {
            if (e < LOW && e > 0) {
                lowAt = t;
                mark = at;
                charged = false;
                rechargedAt = Double.NaN;
            }
            return;
        }
        if (!charged) {
            if (charger != null && charger.contains(at) && e >= RECHARGED) {
                charged = true;
                rechargedAt = t;
            }
        } else if (at.distanceTo(mark) <= RETURN_RADIUS) {
            episodes.add(new Episode(lowAt, mark, rechargedAt, t));
            lowAt = Double.NaN;
        }
    }

    /** {@return the completed episodes, then the open one if any} */
    public List<Episode> episodes() {
        List<Episode> all = new ArrayList<>(episodes);
        if (!Double.isNaN(lowAt)) {
            all.add(new Episode(lowAt, mark, charged ? rechargedAt : Double.NaN, Double.NaN));
        }
        return all;
    }
}
