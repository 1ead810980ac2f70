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

    /**
     * What a camera reads of a ray's hits: which hide what lies behind them, and whether a hit's
     * distance matters within a bracket.
     */
    interface Sight {
        /** {@return whether the hit hides everything behind it} (as the predicate of a fan) */
        boolean opaque(RayHit hit);

        /**
         * {@return whether a hit on an object of this height reads the same at every distance from
         * {@code near} to {@code far}} (both within range, {@code near <= far}): its opacity
         * included. The reader then takes it at any distance of the bracket.
         */
        boolean sameFrom(double near, double far, double height);
    }

    /**
     * A fan as {@link #castFan(Vec2, double[], double, Predicate)} casts it with {@code sight}'s
     * opaque test, for a reader of the hits' distances that {@code sight} describes: a hit's distance
     * may be given as any within a bracket around its own over which {@link Sight#sameFrom} holds,
     * the order of the hits being theirs (the brackets keep apart the hits they would swap).
     */
    default List<List<RayHit>> castFan(Vec2 origin, double[] bearingsDeg, double maxRange, Sight sight) {
        return castFan(origin, bearingsDeg, maxRange, sight::opaque);
    }

    /** {@return the nearest object within range, or null} */
    default RayHit cast(Vec2 origin, double bearingDeg, double maxRange) {
        List<RayHit> hits = castAll(origin, bearingDeg, maxRange);
        return hits.isEmpty() ? null : hits.get(0);
    }
}
