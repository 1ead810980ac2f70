package jacabot.app.cli;

import jacabot.app.run.WorldAtStep;
import jacabot.robot.run.RunRecorder;
import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import java.util.List;

/**
 * An experiment's progress as the world was at each control step: the recorder's events for the
 * agents' console file and, every 10 simulated seconds, the progress line's figures, read on the
 * simulation thread ({@link WorldAtStep}) so that a pipelined run prints what a plain one does at
 * the same step.
 */
final class Progress {
    private static final long EVERY_MS = 10_000;

    /**
     * What a step shows: the recorder's events so far, and the progress line (null between two),
     * a format whose one argument is the run's real-time factor.
     */
    record AtStep(List<String> events, String line) {
    }

    private Progress() {
    }

    /** Reads the world at every step from now; attach after {@code recorder}, whose figures it reads. */
    static WorldAtStep<AtStep> attach(SimWorld world, RunRecorder recorder, Robot robot) {
        long[] next = {EVERY_MS}; // the simulation thread's own
        return WorldAtStep.attach(world, () -> {
            long t = world.timeMs();
            String line = null;
            if (t >= next[0]) {
                next[0] += EVERY_MS;
                var now = recorder.summary("agent");
                line = String.format("  t=%6.1f s  %%5.0fx real time  picked %d  delivered %d%s", t / 1000.0, now.picks(),
                        now.deliveries(), !robot.hasBattery() ? "" : String.format("  battery %.0f J", robot.getBattery().energy()));
            }
            return new AtStep(recorder.events(), line);
        });
    }
}
