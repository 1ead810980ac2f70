package jacabot.app.bench;

/**
 * The repetitions of a simulation benchmark: whole unmeasured runs first, while the JIT compiles,
 * then the measured runs whose median is reported.
 */
final class BenchRuns {
    private BenchRuns() {
    }

    /** @throws IllegalArgumentException unless {@code warmups >= 0} and {@code measuredRuns >= 1} */
    static void check(int warmups, int measuredRuns) {
        if (warmups < 0 || measuredRuns < 1) {
            throw new IllegalArgumentException("warm-up runs must be >= 0 and measured runs >= 1, got " + warmups + " and " + measuredRuns);
        }
    }
}
