package jacabot.cartago;

/** Real time, from {@link System#nanoTime()}: monotonic, unaffected by changes of the date. */
public final class WallClock implements ArtifactClock {
    @Override
    public long nowMillis() {
        return System.nanoTime() / 1_000_000L;
    }

    @Override
    public void sleepUntil(long deadlineMillis) throws InterruptedException {
        for (long left = deadlineMillis - nowMillis(); left > 0; left = deadlineMillis - nowMillis()) {
            Thread.sleep(left);
        }
    }
}
