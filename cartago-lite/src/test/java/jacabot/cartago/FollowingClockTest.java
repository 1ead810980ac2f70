package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class FollowingClockTest {
    @Test
    void followsTheSimulationOnceToldAndNeverGoesBack() {
        var clock = new FollowingClock();
        assertFalse(clock.isFollowing());
        clock.follow(5_000);
        assertTrue(clock.isFollowing());
        assertEquals(5_000, clock.nowMillis());
        clock.follow(4_000);
        assertEquals(5_000, clock.nowMillis(), "simulated time never goes back");
        clock.follow(5_040);
        assertEquals(5_040, clock.nowMillis());
    }

    @Test
    void aSleeperWakesWhenSimulatedTimeReachesItsDeadline() throws Exception {
        var clock = new FollowingClock();
        clock.follow(0);
        var woke = new CountDownLatch(1);
        Thread sleeper = new Thread(() -> {
            try {
                clock.sleepUntil(1_000);
                woke.countDown();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        sleeper.start();
        clock.follow(999);
        assertFalse(woke.await(100, TimeUnit.MILLISECONDS), "not before the deadline");
        clock.follow(1_000);
        assertTrue(woke.await(10, TimeUnit.SECONDS));
    }
}
