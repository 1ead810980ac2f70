package jacabot.app.sweep;

import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.world.AreaSpec;

/**
 * Where things are when a run ends, as tidy-up's success criterion reads it: how many cylinders the
 * world has, how many lie in the storage area (centre within its radius, none carried), and whether
 * the robot stands on the charger (centre within its radius, where the charger charges it).
 */
public record EndState(int cylinders, int stored, boolean parked) {
    /** {@return the end state of a world's snapshot for the robot of that name} */
    public static EndState of(WorldSnapshot w, String robot) {
        int cylinders = 0;
        int stored = 0;
        for (ObjectState o : w.objects()) {
            if (o.kind() == ObjectKind.CYLINDER) {
                cylinders++;
                if (o.carriedBy() == null && within(w.storage(), o.pose().x(), o.pose().z())) {
                    stored++;
                }
            }
        }
        var r = w.robot(robot);
        boolean parked = r != null && within(w.charger(), r.pose().x(), r.pose().z());
        return new EndState(cylinders, stored, parked);
    }

    private static boolean within(AreaSpec area, double x, double z) {
        return area != null && area.contains(x, z);
    }
}
