package jacabot.experiments.link;

import java.util.function.BooleanSupplier;

/**
 * What the link asks about the agent on the other side of the artifact: whether it reasons
 * (liveness: its reasoning cycle moves, or it is idle waiting for events) and whether it is idle
 * (quiescence: it has taken a step's percepts in and acted on them). A probe that throws counts as
 * "no". Recovery, not in the thesis: there the link's threads kept the robot going whatever the agent did.
 */
final class AgentProbes {
    private volatile BooleanSupplier liveness;
    private final BooleanSupplier quiescence;

    AgentProbes(BooleanSupplier liveness, BooleanSupplier quiescence) {
        this.liveness = liveness;
        this.quiescence = quiescence;
    }

    void setLiveness(BooleanSupplier probe) {
        this.liveness = probe;
    }

    boolean alive() {
        try {
            return liveness.getAsBoolean();
        } catch (RuntimeException e) {
            return false;
        }
    }

    boolean idle() {
        try {
            return quiescence.getAsBoolean();
        } catch (RuntimeException e) {
            return false;
        }
    }
}
