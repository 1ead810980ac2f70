package jacabot.cartago.awaiting;

/** Code of the artifact's package, which may call its package-private and protected methods. */
final class SamePackageHelper {
    private SamePackageHelper() {
    }

    static void pause(Waiters w) {
        w.pauseFromOutside();
    }
}
