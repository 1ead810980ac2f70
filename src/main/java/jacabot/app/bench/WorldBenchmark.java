package jacabot.app.bench;

import jacabot.app.world.TeamWorld;
import jacabot.app.world.WorldGenerator;
import jacabot.sim.SimWorld;
import jacabot.sim.demo.Wander;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Files;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The simulator alone: for each experiment world, the wall-clock cost of one control step (physics
 * and every enabled device, camera included) and the real-time factor, with the demo pattern
 * ({@link Wander}) driving; then the team world with 1, 2 and 4 robots and how a step's cost grows
 * with the team. Not a test: figures depend on the machine.
 */
public final class WorldBenchmark {
    private final Path worldsDir;
    private final double seconds;
    private final PrintWriter out;

    public WorldBenchmark(Path worldsDir, double seconds, PrintWriter out) {
        this.worldsDir = worldsDir;
        this.seconds = seconds;
        this.out = out;
    }

    public void run() throws WorldFileException {
        out.printf(Locale.ROOT, "%-20s %10s %14s %12s %10s%n", "world", "sim s", "µs/ctrl step", "RT factor", "contact s");
        for (String name : List.of("obstacle-avoidance", "object-picking", "navigation", "suspend-resume")) {
            measure(name, SimWorld.load(worldsDir.resolve(name + ".json")));
        }
        // a team (thesis Chapter 6): the same world with 1, 2 and 4 robots; the most any robot touched
        Path team = worldsDir.resolve(WorldGenerator.TEAM_DELIVERY + ".json");
        if (Files.isRegularFile(team)) {
            WorldSpec spec = WorldFileReader.read(team);
            double one = 0;
            for (int n : new int[] {1, 2, 4}) {
                if (n <= spec.robots().size()) {
                    double cost = measure("team-delivery x" + n, SimWorld.of(TeamWorld.firstRobots(spec, n)));
                    one = n == 1 ? cost : one;
                    if (n > 1) {
                        out.printf(Locale.ROOT, "%-20s %d robots: %.2fx one robot's step%n", "", n, cost / one);
                    }
                }
            }
        }
    }

    /** {@return the µs per control step of {@code world} driven by the demo pattern, after printing its row} */
    private double measure(String label, SimWorld world) {
        Wander wander = new Wander();
        for (int i = 0; i < 250; i++) { // 10 s of warm-up
            wander.accept(world);
            world.step();
        }
        long steps = Math.max(1, Math.round(seconds * 1000 / world.controlStep()));
        long start = System.nanoTime();
        for (long i = 0; i < steps; i++) {
            wander.accept(world);
            world.step();
        }
        double wall = (System.nanoTime() - start) / 1e9;
        double contact = world.robots().stream().mapToDouble(r -> r.contactTime()).max().orElse(0);
        out.printf(Locale.ROOT, "%-20s %10.0f %14.1f %12.0f %10.1f%n", label, seconds, wall * 1e6 / steps, seconds / wall, contact);
        out.flush();
        return wall * 1e6 / steps;
    }
}
