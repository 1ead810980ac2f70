package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import org.junit.jupiter.api.Test;

/** The lockstep spin's budget against waits of known length, on a clock that moves 1 µs per reading. */
class LockstepSpinTest {
    private long now;
    private final LockstepSpin spin = new LockstepSpin(() -> now += 1_000);

    /** Bytes that arrive after {@code micros} of spinning; counts how often it was asked. */
    private final class Arrival implements LockstepSpin.Ready {
        final long at;
        int asked;

        Arrival(long micros) {
            at = now + micros * 1_000;
        }

        @Override
        public boolean ready() {
            asked++;
            return now >= at;
        }
    }

    private int await(long micros) throws IOException {
        Arrival a = new Arrival(micros);
        spin.await(a);
        return a.asked;
    }

    @Test
    void aWaitWithinTheBudgetEndsWhenTheBytesCome() throws IOException {
        int asked = await(30);
        assertEquals(30, asked, "asked once per microsecond until the bytes came");
        assertEquals(LockstepSpin.INITIAL_BUDGET_NANOS, spin.budgetNanos());
        assertArrayEquals(new long[] {1, 1}, spin.spinsAndCatches());
    }

    @Test
    void longerWaitsWidenTheBudgetToTwiceTheWaitUpToItsCap() throws IOException {
        await(80);
        assertEquals(160_000, spin.budgetNanos());
        await(150);
        assertEquals(LockstepSpin.MAX_BUDGET_NANOS, spin.budgetNanos());
    }

    @Test
    void spinsThatRunOutHalveTheBudgetThenTheEndJustBlocksAndProbesNowAndThen() throws IOException {
        long[] budgets = new long[5];
        for (int i = 0; i < 5; i++) {
            await(1_000_000); // never within a spin
            budgets[i] = spin.budgetNanos();
        }
        assertArrayEquals(new long[] {50_000, 25_000, 12_500, 6_250, 0}, budgets);
        for (int i = 1; i < LockstepSpin.PROBE_EVERY; i++) {
            assertEquals(0, await(10), "no spin while spinning does not pay");
        }
        assertEquals(10, await(10), "the probe spins again, and catches");
        assertEquals(LockstepSpin.INITIAL_BUDGET_NANOS, spin.budgetNanos());
        assertArrayEquals(new long[] {6, 1}, spin.spinsAndCatches());
    }
}
