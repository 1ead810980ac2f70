package jacabot.sim.world;

import java.util.List;

/**
 * A whole world file, parsed and checked. Times: {@code basicTimeStep} and {@code controlStep} in
 * milliseconds (as Webots' {@code WorldInfo.basicTimeStep} and a controller's {@code TIME_STEP});
 * the control step is a multiple of the basic step. {@code storage} and {@code charger} may be null.
 */
public record WorldSpec(String name, ArenaSpec arena, int basicTimeStep, int controlStep, long seed,
                        boolean sensorNoise, List<BoxSpec> walls, List<BoxSpec> boxes,
                        List<CylinderSpec> cylinders, AreaSpec storage, AreaSpec charger,
                        List<RobotSpec> robots, List<EventSpec> events) {
    /** Copies the lists. */
    public WorldSpec {
        walls = List.copyOf(walls);
        boxes = List.copyOf(boxes);
        cylinders = List.copyOf(cylinders);
        robots = List.copyOf(robots);
        events = List.copyOf(events);
    }
}
