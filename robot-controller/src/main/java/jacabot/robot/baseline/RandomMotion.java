package jacabot.robot.baseline;

import jacabot.sim.robot.Robot;
import java.util.Random;

/**
 * The random motion shared by every experiment (thesis Chapter 4 §5, C {@code move()} and Jason
 * {@code !move(N)}): forward for up to 10 s, or an arc to the left or right for up to 5 s followed
 * by 1 s forward. Polled once per control step; it changes the wheel speeds only when a move ends.
 *
 * <p>Fixed from the C listing: it draws left with probability 0.2 and right with 0.3
 * ({@code m <= 0.7}); the Jason plans' 0.25 / 0.25 is used. The C listing leaves durations to the
 * caller; the Jason plans' are used.
 */
final class RandomMotion {
    private final Robot robot;
    private final Random random;
    private final double forward, slow;
    private long moveEndsMs, arcEndsMs = -1;

    /** @param forward the forward wheel speed; arcs slow one wheel to 40 % of it (the C 50/20) */
    RandomMotion(Robot robot, Random random, double forward) {
        this.robot = robot;
        this.random = random;
        this.forward = forward;
        this.slow = forward * 0.4;
    }

    /** Drives on; when the current move is over, draws the next one. */
    void poll(long nowMs) {
        if (arcEndsMs >= 0 && nowMs >= arcEndsMs) {
            arcEndsMs = -1;
            robot.setSpeeds(forward, forward);
        }
        if (nowMs < moveEndsMs) {
            return;
        }
        double m = random.nextDouble();
        if (m <= 0.5) {
            robot.setSpeeds(forward, forward);
            moveEndsMs = nowMs + Math.round(random.nextDouble() * 10_000);
        } else {
            if (m <= 0.75) {
                robot.setSpeeds(slow, forward);
            } else {
                robot.setSpeeds(forward, slow);
            }
            arcEndsMs = nowMs + Math.round(random.nextDouble() * 5_000);
            moveEndsMs = arcEndsMs + 1_000;
        }
    }

    /** After another task drove the wheels: go forward for {@code ms}, then draw again. */
    void resume(long nowMs, long ms) {
        arcEndsMs = -1;
        robot.setSpeeds(forward, forward);
        moveEndsMs = nowMs + ms;
    }
}
