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
            int steps = workspace.runPending();
            long run = mas.runUntilQuiescent(cycleBudget - cycles);
            cycles += run;
            if (steps == 0 && run == 0) {
                break;
            }
        }
        return cycles;
    }
}
