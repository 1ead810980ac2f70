package jacabot.sim.device;

import jacabot.sim.geom.Vec2;
import java.util.ArrayList;
import java.util.List;

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

    /** {@return the nearest object within range, or null} */
    default RayHit cast(Vec2 origin, double bearingDeg, double maxRange) {
        List<RayHit> hits = castAll(origin, bearingDeg, maxRange);
        return hits.isEmpty() ? null : hits.get(0);
    }
}
