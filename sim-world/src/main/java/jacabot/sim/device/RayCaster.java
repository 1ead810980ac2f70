package jacabot.sim.device;

import jacabot.sim.geom.Vec2;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

/** Casts rays on the floor plane for one robot's sensors, ignoring the robot and what it carries. */
public interface RayCaster {
    /** {@return every object the ray crosses within {@code maxRange} metres, nearest first} */
    List<RayHit> castAll(Vec2 origin, double bearingDeg, double maxRange);

    /**
     * Casts a fan of rays from one origin, as a camera does for its columns: {@return for each bearing
     * what {@link #castAll} returns for it}. A caster may share the work between the rays (e.g. find
     * once which objects each ray can reach), never change the result.
     */
    default List<List<RayHit>> castFan(Vec2 origin, double[] bearingsDeg, double maxRange) {
        var all = new ArrayList<List<RayHit>>(bearingsDeg.length);
        for (double b : bearingsDeg) {
            all.add(castAll(origin, b, maxRange));
        }
        return all;
    }

    /**
     * A fan as {@link #castFan(Vec2, double[], double)} casts it, for a caller that reads each ray's
     * hits nearest first only up to the first hit {@code opaque} accepts (what hides everything
     * behind it): a ray's list holds every hit up to and including that one, in the same order, and
     * may leave out what lies beyond, which a caster then need not work out.
     */
    default List<List<RayHit>> castFan(Vec2 origin, double[] bearingsDeg, double maxRange, Predicate<RayHit> opaque) {
        return castFan(origin, bearingsDeg, maxRange);
    }

    /** {@return the nearest object within range, or null} */
    default RayHit cast(Vec2 origin, double bearingDeg, double maxRange) {
        List<RayHit> hits = castAll(origin, bearingDeg, maxRange);
        return hits.isEmpty() ? null : hits.get(0);
    }
}
