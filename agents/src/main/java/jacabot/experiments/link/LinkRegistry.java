package jacabot.experiments.link;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BooleanSupplier;

/**
 * The links open in this process, one per robot, and the agent probes that links opened from now on
 * start with. The agents make their middleware artifacts, and so their links, as they run, so the
 * launcher cannot hand a probe to each link: it sets the process's here, which watch every agent of
 * the process ({@code jacabot run}). A link may be given its own with {@link MiddlewareLink#setLiveness}.
 */
public final class LinkRegistry {
    private static final Set<MiddlewareLink> OPEN = ConcurrentHashMap.newKeySet();
    private static volatile BooleanSupplier defaultLiveness = () -> true;
    private static volatile BooleanSupplier defaultQuiescence = () -> true;

    private LinkRegistry() {
    }

    /**
     * Closes every link of this process at once (the launcher, when an agent's thread died): the
     * controllers see the drop and stop their robots without waiting for the process to end.
     */
    public static void closeAll() {
        for (MiddlewareLink l : OPEN) {
            l.close();
        }
    }

    /** The liveness probe of links opened from now on ({@link MiddlewareLink#setLiveness}). */
    public static void setDefaultLiveness(BooleanSupplier probe) {
        defaultLiveness = probe;
    }

    /**
     * The quiescence probe of links opened from now on: with the agents in their own threads, a
     * lockstep step is acknowledged once it says they are idle ({@link MiddlewareLink#acknowledgeWhenAlive});
     * by default at once.
     */
    public static void setDefaultQuiescence(BooleanSupplier probe) {
        defaultQuiescence = probe;
    }

    /** {@return a new link's probes: the process's defaults now} */
    static AgentProbes probes() {
        return new AgentProbes(defaultLiveness, defaultQuiescence);
    }

    static void opened(MiddlewareLink link) {
        OPEN.add(link);
    }

    static void closed(MiddlewareLink link) {
        OPEN.remove(link);
    }
}
