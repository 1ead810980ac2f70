package jacabot.experiments.link;

import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.SensorKind;
import jacabot.sim.SimWorld;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

/** What the link's tests share (and the root project's, which run the link across processes). */
public final class LinkTestSupport {
    /**
     * How long a condition may take: generous, since a machine at load 30 and more stalls threads
     * for seconds; a condition met returns at once, so passing runs do not wait for it.
     */
    static final int DEADLINE_S = 60;

    private LinkTestSupport() {
    }

    /** {@return a world file of the repository's {@code worlds/}} */
    public static SimWorld world(String name) throws Exception {
        return SimWorld.load(Path.of(System.getProperty("jacabot.rootDir", "."), "worlds", name + ".json"));
    }

    /** Safety net only: the first event matching within {@link #DEADLINE_S} seconds. */
    public static LinkEvent await(MiddlewareLink link, Predicate<LinkEvent> p) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(DEADLINE_S);
        while (System.nanoTime() < end) {
            LinkEvent e = link.poll(100, TimeUnit.MILLISECONDS);
            if (e != null && p.test(e)) {
                return e;
            }
        }
        throw new AssertionError("no matching event within " + DEADLINE_S + " s");
    }

    /** {@return a test for the wheel speed reading {@code (left, right)}} */
    public static Predicate<LinkEvent> wheels(double left, double right) {
        return e -> e instanceof LinkEvent.Reading && ((LinkEvent.Reading) e).info().getId() == SensorKind.WHEEL_SPEEDS.id()
                && Arrays.equals(((LinkEvent.Reading) e).info().getDoubleValues(), new double[] {left, right});
    }

    /** Safety net only: fails when {@code condition} does not hold within 10 s. */
    public static void waitFor(BooleanSupplier condition) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(DEADLINE_S);
        while (!condition.getAsBoolean() && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        assertTrue(condition.getAsBoolean(), "condition not met within " + DEADLINE_S + " s");
    }
}
