package jacabot.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class SimRunnerTest {
    @Test
    void stepModeRunsTheControllerThenOneControlStep() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        List<Long> seen = new ArrayList<>();
        SimRunner r = new SimRunner(w, world -> seen.add(world.timeMs()));
        r.setMode(SimRunner.Mode.STEP);
        r.stepOnce();
        r.stepOnce();
        assertEquals(List.of(0L, 40L), seen);
        assertEquals(80, w.timeMs());
    }

    @Test
    void fastModeRunsAGivenSimulatedDurationAndGivesTheSameRunAsSteppingByHand() {
        SimWorld a = TestWorlds.khepera(0, 0, 0, ""), b = TestWorlds.khepera(0, 0, 0, "");
        SimRunner r = new SimRunner(a, world -> world.robot("k").setSpeeds(100, 40));
        r.setMode(SimRunner.Mode.FAST);
        r.runFor(3.0);
        for (int i = 0; i < 75; i++) {
            b.robot("k").setSpeeds(100, 40);
            b.step();
        }
        assertEquals(3000, a.timeMs());
        assertEquals(b.robot("k").trajectory(), a.robot("k").trajectory());
    }

    @Test
    void stepDurationsMustBeMultiplesOfTheBasicTimeStep() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        assertThrows(IllegalArgumentException.class, () -> w.step(12));
        assertThrows(IllegalArgumentException.class, () -> w.step(0));
        assertThrows(IllegalArgumentException.class, () -> new SimRunner(w, null).setSpeedFactor(0));
    }

    /** A console thread stamps its lines with the clock while a step (the world's lock held) waits to print. */
    @Test
    void theClockIsReadWithoutWaitingForAStepInProgress() throws Exception {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        w.step();
        var inStep = new CountDownLatch(1);
        var release = new CountDownLatch(1);
        var holder = new Thread(() -> {
            synchronized (w) { // as SimRunner.stepOnce holds it while the controller's listeners run
                inStep.countDown();
                try {
                    release.await(10, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        });
        holder.start();
        try {
            assertTrue(inStep.await(10, TimeUnit.SECONDS));
            var read = CompletableFuture.supplyAsync(() -> w.timeMs() + (long) (w.time() * 1000));
            assertEquals(80L, read.get(5, TimeUnit.SECONDS));
        } finally {
            release.countDown();
            holder.join();
        }
    }
}
