package jacabot.app.bench;

import jacabot.sim.SimWorld;
import jacabot.sim.demo.Wander;
import jacabot.sim.io.WorldFileException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The simulator alone: for each experiment world, the wall-clock cost of one control step (physics
 * and every enabled device, camera included) and the real-time factor, with the demo pattern
 * ({@link Wander}) driving. Not a test: figures depend on the machine.
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
            SimWorld world = SimWorld.load(worldsDir.resolve(name + ".json"));
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
            out.printf(Locale.ROOT, "%-20s %10.0f %14.1f %12.0f %10.1f%n", name, seconds, wall * 1e6 / steps,
                    seconds / wall, world.robots().get(0).contactTime());
            out.flush();
        }
    }
}
