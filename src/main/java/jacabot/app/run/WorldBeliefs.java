package jacabot.app.run;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.robot.Experiment;
import jacabot.sim.world.WorldSpec;
import java.util.ArrayList;
import java.util.List;

/**
 * What the robot is told about its world when it starts (not in the thesis: the agents take their landmarks from the world, so other worlds work): the landmarks of the world
 * file become initial beliefs, so no coordinate is written in an agent. {@code arena(Width, Depth)}
 * (centred on the origin), {@code storagePoint(X, Z)} with {@code storageRadius(R)}, and
 * {@code charger(X, Z)} when the world has them, in the GPS coordinates of {@code location(X, Y, Z)}. A belief of the same name and arity
 * in the program (e.g. the thesis' literal {@code storagePoint(0.41, -0.41)}) is replaced, as the
 * two-process set-up does with the {@code .mas2j} option {@code beliefs="..."}.
 */
public final class WorldBeliefs {
    private WorldBeliefs() {
    }

    /** {@return the landmark beliefs of a world} */
    public static List<Literal> of(WorldSpec spec) {
        var out = new ArrayList<Literal>();
        out.add(Literal.of("arena", NumberTerm.of(spec.arena().width()), NumberTerm.of(spec.arena().depth())));
        if (spec.storage() != null) {
            out.add(Literal.of("storagePoint", NumberTerm.of(spec.storage().x()), NumberTerm.of(spec.storage().z())));
            // how near the point a cylinder counts as delivered: the agent keeps clear of that area
            out.add(Literal.of("storageRadius", NumberTerm.of(spec.storage().radius())));
        }
        if (spec.charger() != null) {
            out.add(Literal.of("charger", NumberTerm.of(spec.charger().x()), NumberTerm.of(spec.charger().z())));
        }
        return out;
    }

    /**
     * {@return the landmark beliefs of a world for an experiment: tidy-up's task also names how many
     * cylinders there are to store, {@code cylinders(N)}, and how many of them lie in the storage area
     * already, {@code stored(K)}, when some do}
     */
    public static List<Literal> of(WorldSpec spec, Experiment experiment) {
        var out = new ArrayList<Literal>(of(spec));
        if (experiment == Experiment.TIDY_UP) {
            out.add(Literal.of("cylinders", NumberTerm.of(spec.cylinders().size())));
            long stored = storedAtStart(spec);
            if (stored > 0) {
                out.add(Literal.of("stored", NumberTerm.of(stored)));
            }
        }
        return out;
    }

    /**
     * {@return how many of the world's cylinders start in the storage area} (centre within its radius,
     * the success criterion's test, {@link jacabot.sim.world.AreaSpec#contains(double, double)}): they
     * count as stored from the start, so tidy-up's agent is told {@code stored(K)} in place of its
     * delivery skill's {@code stored(0)}; none when there are none (the generator keeps the area free
     * of cylinders; a hand-made world or a scripted move may not)
     */
    static long storedAtStart(WorldSpec spec) {
        return spec.storage() == null ? 0
                : spec.cylinders().stream().filter(c -> spec.storage().contains(c.x(), c.z())).count();
    }

    /**
     * Tells every agent of tidy-up when its task ends, a run of {@code seconds} from {@code nowMs}
     * of simulated time, as a belief of the agent's clock, {@code taskEnd(Ms)}, so that no recharge
     * trip is made that the battery does not need before then (skills/recharge-trip.asl); nothing to
     * the other experiments, whose recharge episodes are the task itself. Before the agents' first
     * reasoning cycle, as an initial belief.
     */
    static void tellTaskEnd(LocalMAS mas, Experiment experiment, long nowMs, double seconds) {
        if (experiment == Experiment.TIDY_UP) {
            tellTeamTaskEnd(mas, nowMs, seconds);
        }
    }

    /**
     * Tells every agent of a team's run when its task ends, {@code taskEnd(Ms)} as tidy-up's: a
     * team's deliveries end with the run too, and a charger trip the battery does not need before
     * then kept a robot from the last cylinders and from the charger a teammate needed.
     */
    static void tellTeamTaskEnd(LocalMAS mas, long nowMs, double seconds) {
        Literal b = Literal.of("taskEnd", NumberTerm.of(nowMs + Math.round(seconds * 1000))).addAnnot(Literal.SOURCE_SELF);
        mas.agentNames().forEach(n -> mas.agent(n).addBelief(b, false));
    }

    /** {@return the program with the world's beliefs first, replacing the program's own of the same name and arity} */
    public static AgentProgram inject(AgentProgram program, WorldSpec spec) {
        return inject(program, spec, null);
    }

    /** {@return the program with the world's beliefs for the experiment first (see {@link #of(WorldSpec, Experiment)})} */
    public static AgentProgram inject(AgentProgram program, WorldSpec spec, Experiment experiment) {
        List<Literal> world = of(spec, experiment);
        var beliefs = new ArrayList<Object>(world);
        for (Object b : program.beliefs()) {
            if (!(b instanceof Literal l && world.stream().anyMatch(w -> w.functor().equals(l.functor()) && w.arity() == l.arity()))) {
                beliefs.add(b);
            }
        }
        return new AgentProgram(program.file(), beliefs, program.goals(), program.plans());
    }

    /** {@return the beliefs as the {@code .mas2j} option {@code beliefs="..."} writes them} */
    public static String asOption(WorldSpec spec) {
        return String.join(", ", of(spec).stream().map(Literal::toString).toList());
    }
}
