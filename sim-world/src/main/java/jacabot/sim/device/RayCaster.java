package jacabot.sim.device;

import jacabot.sim.geom.Vec2;
import java.util.List;

/** Casts rays on the floor plane for one robot's sensors, ignoring the robot and what it carries. */
public interface RayCaster {
    /** {@return every object the ray crosses within {@code maxRange} metres, nearest first} */
    List<RayHit> castAll(Vec2 origin, double bearingDeg, double maxRange);

    /** {@return the nearest object within range, or null} */
    default RayHit cast(Vec2 origin, double bearingDeg, double maxRange) {
        List<RayHit> hits = castAll(origin, bearingDeg, maxRange);
        return hits.isEmpty() ? null : hits.get(0);
    }
}
