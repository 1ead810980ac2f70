package jacabot.app.run;

import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldListener;
import java.util.Random;
import java.util.concurrent.locks.LockSupport;

/**
 * Which side of a lockstep run the tests slow down at random steps (a quarter of them, up to 2 ms
 * each, unseeded on purpose): a run that is a function of world, agent and seed gives the same
 * logs whichever thread is the slower one.
 */
public enum TimingJitter {
    NONE, WORLD, AGENT;

    /** Slows this side of {@code run}, whose world is {@code world}; call before the run starts. */
    public void apply(SimWorld world, LockstepRun run) {
        Random timing = new Random();
        if (this == WORLD) {
            world.addListener(new WorldListener() {
                @Override
                public void controlStepEnded(long timeMs) {
                    pause(timing);
                }
            });
        } else if (this == AGENT) {
            run.onStep(d -> pause(timing)); // on the agent side's thread, before it answers
        }
    }

    private static void pause(Random timing) {
        if (timing.nextInt(4) == 0) {
            LockSupport.parkNanos(timing.nextInt(2_000_000));
        }
    }
}
