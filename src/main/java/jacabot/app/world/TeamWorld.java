package jacabot.app.world;

import jacabot.sim.world.EventSpec;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * A world for a team of N robots (team-delivery, thesis Chapter 6): a world file holds up to as
 * many robots as a team may have, and a run with N keeps the first N, in the file's order. What the
 * team experiment needs of a world is checked before a run, as {@link Landmarks} does for one robot.
 */
public final class TeamWorld {
    private TeamWorld() {
    }

    /** {@return one line naming the file and what it lacks for a team of {@code robots}, or empty} */
    public static Optional<String> missing(WorldSpec spec, int robots, String file) {
        String needs = "the " + WorldGenerator.TEAM_DELIVERY + " experiment ";
        if (spec.robots().size() < robots) {
            return Optional.of(file + ": $.robots: " + needs + "with " + robots + " robots needs as many; the world has "
                    + spec.robots().size());
        }
        for (int i = 0; i < robots; i++) {
            if (!spec.robots().get(i).model().equals("khepera")) {
                return Optional.of(file + ": $.robots[" + i + "].model: " + needs + "needs Kheperas (camera, gripper, "
                        + "battery); '" + spec.robots().get(i).name() + "' is a " + spec.robots().get(i).model());
            }
        }
        if (spec.storage() == null) {
            return Optional.of(file + ": $.storage: " + needs + "needs a storage point; the world has none");
        }
        if (spec.charger() == null) {
            return Optional.of(file + ": $.charger: " + needs + "needs a charger; the world has none");
        }
        return Optional.empty();
    }

    /**
     * {@return the world with its first {@code robots} robots only}
     *
     * @throws IllegalArgumentException when the world has fewer, or an event names a robot left out
     */
    public static WorldSpec firstRobots(WorldSpec spec, int robots) {
        if (robots < 1 || robots > spec.robots().size()) {
            throw new IllegalArgumentException("the world " + spec.name() + " has " + spec.robots().size() + " robots, not "
                    + robots);
        }
        List<RobotSpec> kept = spec.robots().subList(0, robots);
        Set<String> names = kept.stream().map(RobotSpec::name).collect(Collectors.toSet());
        for (EventSpec e : spec.events()) {
            String robot = e.trigger() instanceof EventSpec.Near n ? n.robot()
                    : e.action() instanceof EventSpec.Knock k ? k.robot()
                    : e.action() instanceof EventSpec.Drain d ? d.robot() : null;
            if (robot != null && !names.contains(robot)) {
                throw new IllegalArgumentException("an event of the world " + spec.name() + " names robot '" + robot
                        + "', which a team of " + robots + " leaves out");
            }
        }
        return new WorldSpec(spec.name(), spec.arena(), spec.basicTimeStep(), spec.controlStep(), spec.seed(), spec.sensorNoise(),
                spec.walls(), spec.boxes(), spec.cylinders(), spec.storage(), spec.charger(), kept, spec.events());
    }
}
