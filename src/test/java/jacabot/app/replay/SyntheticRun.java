package jacabot.app.replay;

import jacabot.app.inspector.MindState;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * A recorded run made up for tests, long and cheap: a step log of {@code seconds} of 40 ms steps
 * in the navigation world, the robot on a known path ({@link #x}, {@link #z}), a belief
 * {@code second(S)} changing every second, a plan selected every 5 s and a failed goal every minute.
 */
public final class SyntheticRun {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    private SyntheticRun() {
    }

    /** {@return the robot's x at {@code ms}: from -0.4 to 0.4 m over the run} */
    public static double x(long ms, long totalMs) {
        return StepLog.round(-0.4 + 0.8 * ms / totalMs);
    }

    /** {@return the robot's z at {@code ms}: a slow wave, ±0.3 m} */
    public static double z(long ms) {
        return StepLog.round(0.3 * Math.sin(ms / 60_000.0 * 2 * Math.PI));
    }

    /** Writes {@code dir}/steps.jsonl.gz. */
    public static void write(Path dir, int seconds) throws IOException, WorldFileException {
        SimWorld w = SimWorld.load(ROOT.resolve("worlds/navigation.json"));
        var header = new StepLog.Header(StepLog.FORMAT, "navigation", w.name(), 1, 40, w.robots().get(0).name(),
                "synthetic.asl", w.snapshot(), null);
        long total = seconds * 1000L;
        try (var log = new StepLog.Writer(dir.resolve(StepLog.FILE), header)) {
            for (long t = 40; t <= total; t += 40) {
                var beliefs = List.of(new MindState.Belief("second(" + t / 1000 + ")", List.of("self"), List.of()));
                List<MindState.Selection> sel = t % 60_000 == 0
                        ? List.of(new MindState.Selection(t, t / 40, 1, "-!tick(" + t / 5000
                                + ")[code(go),error(no_applicable),error_msg(\"no plan\")]", "@giveUp -!tick(N)", "{N=1}"))
                        : t % 5000 == 0
                        ? List.of(new MindState.Selection(t, t / 40, 1, "+!tick(" + t / 5000 + ")", "@tick +!tick(N)", "{N=" + t / 5000 + "}"))
                        : List.of();
                var mind = new MindState("robot", t / 40, t, t / 40, beliefs, List.of(), List.of(), sel);
                log.stepText(t, new StepLog.Body(x(t, total), z(t), (t / 100) % 360, 500.0, 1, 1, null, 0), List.of(),
                        List.of(), mind, w.supervisor().objects());
            }
        }
    }
}
