package jacabot.sim.bench;

import jacabot.sim.SimWorld;
import jacabot.sim.demo.Wander;
import jacabot.sim.io.WorldFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * Prints, for each experiment world, the wall-clock cost of one control step (physics + every
 * enabled device, camera included) and the real-time factor, with the robot driving the
 * {@link Wander} pattern. Not a test: figures depend on the machine.
 * Usage: {@code SimBenchmark [WORLDS_DIR] [SECONDS]} (defaults: worlds, 300 s simulated per world).
 */
public final class SimBenchmark {
    private SimBenchmark() {
    }

    public static void main(String[] args) throws WorldFileException {
        Path dir = Path.of(args.length > 0 ? args[0] : "worlds");
        double seconds = args.length > 1 ? Double.parseDouble(args[1]) : 300;
        System.out.printf(Locale.ROOT, "%-20s %10s %14s %12s %10s%n", "world", "sim s", "µs/ctrl step", "RT factor", "contact s");
        for (String name : List.of("obstacle-avoidance", "object-picking", "navigation", "suspend-resume")) {
            SimWorld world = SimWorld.load(dir.resolve(name + ".json"));
            Wander wander = new Wander();
            for (int i = 0; i < 250; i++) { // 10 s of warm-up
                wander.accept(world);
                world.step();
            }
            long steps = Math.round(seconds * 1000 / world.controlStep());
            long start = System.nanoTime();
            for (long i = 0; i < steps; i++) {
                wander.accept(world);
                world.step();
            }
            double wall = (System.nanoTime() - start) / 1e9;
            System.out.printf(Locale.ROOT, "%-20s %10.0f %14.1f %12.0f %10.1f%n", name, seconds, wall * 1e6 / steps,
                    seconds / wall, world.robots().get(0).contactTime());
        }
    }
}
