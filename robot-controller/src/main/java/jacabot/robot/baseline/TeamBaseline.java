package jacabot.robot.baseline;

import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Phaser;

/**
 * A team without coordination (thesis Chapter 6; the reference a team of agents must beat): one
 * copy of experiment 4's procedural baseline ({@link SuspendResumeBaseline}) per robot of the world,
 * each on its own thread as each C program is a Webots controller process of its own, and the world
 * stepped once every controller has asked for the next step, as Webots does with several
 * controllers in lockstep. A controller touches only its own robot between two steps, so the run is
 * the same for the same world and seed however the threads are scheduled. Robot i (from 0) draws its
 * random motion from {@code seed + i}: a team of one is the single baseline's run.
 */
public final class TeamBaseline {
    private TeamBaseline() {
    }

    /** A finished run: the world as it ended, and each robot's recorder and summary, in the world's order. */
    public record TeamRun(SimWorld world, List<RunRecorder> recorders, List<RunSummary> summaries) {
        /** {@return the team's deliveries} */
        public int deliveries() {
            return summaries.stream().mapToInt(RunSummary::deliveries).sum();
        }
    }

    /**
     * Runs every robot of {@code world} for {@code seconds} of simulated time.
     *
     * @throws IllegalStateException when a controller failed (its robot stopped; the others ran on)
     */
    public static TeamRun run(SimWorld world, long seed, double seconds) throws InterruptedException {
        List<Robot> robots = world.robots();
        Phaser turn = new Phaser(robots.size()) {
            @Override
            protected boolean onAdvance(int phase, int parties) {
                if (parties > 0) {
                    world.step(); // by the last controller to ask: every robot has acted for this step
                }
                return parties == 0;
            }
        };
        List<RunRecorder> recorders = new ArrayList<>();
        List<BaselineController> controllers = new ArrayList<>();
        for (int i = 0; i < robots.size(); i++) {
            RunRecorder recorder = RunRecorder.attach(world, robots.get(i).name());
            BaselineController c = new SuspendResumeBaseline(world, robots.get(i).name(), seed + i, recorder::note);
            c.stepWith(turn::arriveAndAwaitAdvance);
            recorders.add(recorder);
            controllers.add(c);
        }
        List<Thread> threads = new ArrayList<>();
        Throwable[] failure = new Throwable[1];
        for (BaselineController c : controllers) {
            Thread t = new Thread(() -> {
                try {
                    c.runFor(seconds);
                } catch (RuntimeException | Error e) {
                    synchronized (failure) {
                        failure[0] = failure[0] == null ? e : failure[0];
                    }
                    c.robot.setSpeeds(0, 0);
                    turn.arriveAndDeregister(); // the others go on without it
                }
            }, "baseline-" + c.robot.name());
            t.setDaemon(true);
            threads.add(t);
        }
        threads.forEach(Thread::start);
        for (Thread t : threads) {
            t.join();
        }
        if (failure[0] != null) {
            throw new IllegalStateException("a team baseline failed: " + failure[0], failure[0]);
        }
        List<RunSummary> summaries = new ArrayList<>();
        for (RunRecorder r : recorders) {
            summaries.add(r.summary(BaselineRunner.CONTROLLER));
        }
        return new TeamRun(world, recorders, summaries);
    }
}
