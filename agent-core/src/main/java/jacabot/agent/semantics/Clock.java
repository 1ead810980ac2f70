package jacabot.agent.semantics;

import java.time.LocalTime;

/** Time as the agents see it ({@code .wait}, {@code .time}): the wall clock or simulated time. */
public interface Clock {
    /** {@return milliseconds since an arbitrary origin; never decreases} */
    long millis();

    /** {@return the time of day for {@code .time}: simulated time starts at midnight} */
    default LocalTime timeOfDay() {
        return LocalTime.ofNanoOfDay((millis() % 86_400_000L) * 1_000_000L);
    }

    /** The wall clock (milliseconds since the clock was made; {@code .time} gives the real time). */
    static Clock wall() {
        long origin = System.nanoTime();
        return new Clock() {
            @Override
            public long millis() {
                return (System.nanoTime() - origin) / 1_000_000L;
            }

            @Override
            public LocalTime timeOfDay() {
                return LocalTime.now();
            }
        };
    }
}
