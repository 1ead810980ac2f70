package jacabot.cartago.bridge;

import jacabot.agent.runtime.LocalMAS;
import jacabot.cartago.Workspace;

/**
 * Deterministic stepping of agents and a stepped workspace together: artifact steps, then agent
 * cycles, until neither has anything left to do. Lockstep simulation calls this once per control
 * step; tests call it to run a JaCa system reproducibly.
 */
public final class JacaStepper {
    private final LocalMAS mas;
    private final Workspace workspace;
    private long artifactNanos;
    private long reasoningNanos;
    private long artifactSteps;

    public JacaStepper(LocalMAS mas, Workspace workspace) {
        if (workspace.mode() != Workspace.Mode.STEPPED) {
            throw new IllegalArgumentException("the workspace must be stepped");
        }
        this.mas = mas;
        this.workspace = workspace;
    }

    /**
     * Runs until quiescent, or until {@code cycleBudget} reasoning cycles have run.
     * {@return the number of reasoning cycles run}
     */
    public long runUntilQuiescent(long cycleBudget) {
        long cycles = 0;
        while (!mas.isStopped() && cycles < cycleBudget) {
            long t0 = System.nanoTime();
            int steps = workspace.runPending();
            long t1 = System.nanoTime();
            long run = mas.runUntilQuiescent(cycleBudget - cycles);
            artifactNanos += t1 - t0;
            reasoningNanos += System.nanoTime() - t1;
            cycles += run;
            artifactSteps += steps;
            if (steps == 0 && run == 0) {
                break;
            }
        }
        return cycles;
    }

    /** {@return wall-clock nanoseconds spent running artifact steps so far} */
    public long artifactNanos() {
        return artifactNanos;
    }

    /** {@return how many artifact steps (operations and their resumptions after an await) have run so far} */
    public long artifactSteps() {
        return artifactSteps;
    }

    /** {@return wall-clock nanoseconds spent in reasoning cycles so far} */
    public long reasoningNanos() {
        return reasoningNanos;
    }
}
