package jacabot.cartago;

/**
 * A clock that reads the wall clock until it is told the time of a simulation, and from then on
 * follows that time: the robot controller sends the simulated time with its readings, and the
 * middleware artifact passes it on ({@link #follow(long)}), so that {@code await_time} and the
 * agents' {@code .wait} count simulated time whatever the simulation's speed. Thread-safe.
 */
public final class FollowingClock implements ArtifactClock {
    private final long origin = System.nanoTime();
    private boolean following;
    private long simulated;

    @Override
    public synchronized long nowMillis() {
        return following ? simulated : (System.nanoTime() - origin) / 1_000_000L;
    }

    /** {@return whether the clock follows a simulation (it has been told its time)} */
    public synchronized boolean isFollowing() {
        return following;
    }

    /** Moves to the simulation's time (never backwards). */
    public synchronized void follow(long simulatedMillis) {
        if (!following || simulatedMillis > simulated) {
            simulated = Math.max(simulatedMillis, following ? simulated : 0);
            following = true;
            notifyAll();
        }
    }

    @Override
    public void sleepUntil(long deadlineMillis) throws InterruptedException {
        synchronized (this) {
            while (following && simulated < deadlineMillis) {
                wait();
            }
        }
        for (long left = deadlineMillis - nowMillis(); left > 0; left = deadlineMillis - nowMillis()) {
            synchronized (this) {
                if (following) {
                    while (simulated < deadlineMillis) {
                        wait();
                    }
                    return;
                }
                wait(Math.min(left, 50));
            }
        }
    }
}
