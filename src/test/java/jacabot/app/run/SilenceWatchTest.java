package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The link's silence on a clock of the test's own: looks once a second, a process stopped between two. */
class SilenceWatchTest {
    private final long[] now = {0};
    private final SilenceWatch watch = new SilenceWatch(60, () -> now[0]);

    /** Looks once a second for the given seconds; whether any look found the silence too long. */
    private boolean lookFor(int seconds) {
        boolean tooLong = false;
        for (int i = 0; i < seconds; i++) {
            now[0] += TimeUnit.SECONDS.toNanos(1);
            tooLong |= watch.tooLong();
        }
        return tooLong;
    }

    @Test
    void sixtyOneSecondsOfSilenceAreTooLong() {
        assertFalse(lookFor(60));
        assertTrue(lookFor(1));
    }

    @Test
    void hearingTheOtherSideStartsTheCountAgain() {
        assertFalse(lookFor(50));
        watch.heard();
        assertFalse(lookFor(50));
        assertTrue(lookFor(11));
    }

    @Test
    void aStoppedProcessDoesNotCountItsStopAsSilence() {
        assertFalse(lookFor(30));
        now[0] += TimeUnit.MINUTES.toNanos(5); // SIGSTOP for five minutes, then SIGCONT
        assertFalse(watch.tooLong(), "the first look after the stop");
        assertFalse(lookFor(27));
        assertTrue(lookFor(2), "the silence the watcher was awake for still ends the run");
    }
}
