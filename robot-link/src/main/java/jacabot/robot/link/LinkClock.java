package jacabot.robot.link;

import java.time.Instant;

/**
 * The clock both sides stamp readings and commands with, in microseconds since the epoch, so
 * that a time taken by the controller process and one taken by the agent platform can be
 * subtracted when both run on one machine (thesis Chapter 5 §3: reactive and response time).
 * Tests inject their own.
 */
@FunctionalInterface
public interface LinkClock {
    /** {@return microseconds since 1970-01-01T00:00Z} */
    long nowMicros();

    /** {@return the system clock (microsecond resolution where the platform offers it)} */
    static LinkClock system() {
        return () -> {
            Instant now = Instant.now();
            return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000;
        };
    }
}
