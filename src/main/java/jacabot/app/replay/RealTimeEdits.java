package jacabot.app.replay;

import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.AgentProgram;
import jacabot.app.inspector.ConsoleRecorder;
import jacabot.app.inspector.RunEdits;
import jacabot.app.inspector.WhatIfJob;
import jacabot.app.run.AgentSource;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.LongSupplier;

/**
 * The inspector page's edits of a live real-time run: the edited program's plans replace the
 * running agent's at the start of its next reasoning cycle, on its own thread (as Jason's reload
 * of plans: beliefs, goals and intentions stay; the plans chosen from then on are the edited
 * ones). A real-time run cannot be run again step for step, so it starts no what-if.
 */
public final class RealTimeEdits implements RunEdits {
    /** How long a reload waits for the agent's next cycle (an agent that reasons at all starts one in milliseconds). */
    static final long WAIT_MS = 10_000;
    private static final int WAITING = 0, APPLIED = 1, GIVEN_UP = 2;

    private final AgentSource original;
    private final Agent agent;
    private final LongSupplier clockMs;
    private final ConsoleRecorder console;
    private final long waitMs;

    /**
     * @param clockMs the run's simulated time (ms)
     * @param console where the swap is marked in the run's console file, or null
     */
    public RealTimeEdits(AgentSource original, Agent agent, LongSupplier clockMs, ConsoleRecorder console) {
        this(original, agent, clockMs, console, WAIT_MS);
    }

    RealTimeEdits(AgentSource original, Agent agent, LongSupplier clockMs, ConsoleRecorder console, long waitMs) {
        this.original = original;
        this.agent = agent;
        this.clockMs = clockMs;
        this.console = console;
        this.waitMs = waitMs;
    }

    @Override
    public String source() {
        return original.text();
    }

    @Override
    public String whatIfRefusal() {
        return WhatIf.REAL_TIME_REFUSAL + "; this run's plans can change as it runs: \"apply these plans to the running agent\"";
    }

    @Override
    public void whatIf(WhatIfJob job, String program) {
        throw new IllegalStateException(whatIfRefusal());
    }

    @Override
    public Reload reloads() {
        return Reload.AT_NEXT_CYCLE;
    }

    @Override
    public String reload(String program) throws Exception {
        AgentProgram edited = WhatIf.parseEdited(original.withText(program)); // nothing is applied when it does not parse
        var state = new AtomicInteger(WAITING);
        var applied = new CompletableFuture<String>();
        agent.runAtBeginOfNextCycle(() -> { // on the agent's thread, between two cycles: its plans can change
            if (!state.compareAndSet(WAITING, APPLIED)) {
                return; // the page was told that nothing was applied
            }
            try {
                WhatIf.swapPlans(agent, edited);
                long t = clockMs.getAsLong();
                if (console != null) {
                    console.line(t, "reload: the plans edited on the inspector's page from here on");
                }
                applied.complete(String.format(Locale.ROOT, "applied to the running agent at t = %.2f s: the plans it "
                        + "chooses from its reasoning cycle %d on are the edited program's", t / 1000.0, agent.cycles()));
            } catch (RuntimeException e) {
                applied.completeExceptionally(e);
            }
        });
        try {
            return applied.get(waitMs, TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            if (state.compareAndSet(WAITING, GIVEN_UP)) {
                throw new IllegalStateException("the agent started no reasoning cycle within " + waitMs / 1000
                        + " s (has the run ended?): nothing applied");
            }
            return applied.get(); // being applied right now
        } catch (ExecutionException e) {
            throw new IllegalStateException("the plans could not be swapped: " + e.getCause(), e.getCause());
        }
    }
}
