package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicInteger;

/** The plan library: plans in file order, each with a unique label ({@code p__N} when unnamed). */
public final class PlanLibrary {
    private final List<Plan> plans = new ArrayList<>();
    /** Jason's kqmlPlans: how messages are handled by plans, after the agent's own plans, never listed. */
    private List<Plan> kqmlPlans = List.of();
    /** Numbers the unnamed plans; a MAS shares one among its agents, as Jason's labels are numbered JVM-wide. */
    private AtomicInteger lastLabel = new AtomicInteger();
    private boolean goalStatePlans;
    private boolean jagPlans;
    /** Candidates by trigger kind and predicate, rebuilt lazily after the library changes. */
    private final HashMap<CandidateKey, List<Plan>> candidateCache = new HashMap<>();
    private int version;

    /** A trigger's kind and predicate (equality written out: it is looked up for every event). */
    private static final class CandidateKey {
        private final Trigger.Op op;
        private final Trigger.Type type;
        private final String functor;
        private final int arity;
        private final boolean negated;
        /** The namespace (null: the default one; a variable stands for any). */
        private final Term ns;

        CandidateKey(Trigger.Op op, Trigger.Type type, String functor, int arity, boolean negated, Term ns) {
            this.ns = ns;
            this.op = op;
            this.type = type;
            this.functor = functor;
            this.arity = arity;
            this.negated = negated;
        }

        /** {@return whether this is the key of a trigger with this kind and literal} */
        boolean matches(Trigger.Op o, Trigger.Type t, Literal l) {
            return o == op && t == type && l.arity() == arity && l.negated() == negated && l.functor().equals(functor)
                    && Objects.equals(l.ns(), ns);
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof CandidateKey k && k.op == op && k.type == type && k.arity == arity
                    && k.negated == negated && k.functor.equals(functor) && Objects.equals(k.ns, ns);
        }

        @Override
        public int hashCode() {
            return ((functor.hashCode() * 31 + arity) * 8 + op.ordinal() * 2 + (negated ? 1 : 0)) * 4 + type.ordinal();
        }
    }

    /**
     * Numbers this library's unnamed plans ({@code p__N}) from a counter shared with other
     * libraries: in Jason the plans of the second agent loaded go on from the first's.
     */
    public void shareLabelCounter(AtomicInteger counter) {
        lastLabel = counter;
    }

    /** Adds a plan (at the end, or at the beginning); names it and marks its source. */
    public Plan add(Plan p, boolean atBeginning) {
        Literal label = p.label();
        if (label == null) {
            label = uniqueLabel();
        } else if (label.functor().equals("undefined")) {
            label = uniqueLabel().withAnnots(label.annots());
        }
        if (!label.hasSource()) {
            label = label.addAnnot(Literal.SOURCE_SELF);
        }
        Plan named = p.withLabel(label);
        changed();
        goalStatePlans |= p.trigger().op() == Trigger.Op.GOAL_STATE;
        jagPlans |= p.trigger().literal() instanceof Literal l && l.functor().startsWith("jag_");
        if (atBeginning) {
            plans.add(0, named);
        } else {
            plans.add(named);
        }
        return named;
    }

    /**
     * Adds a plan told by {@code source} ({@code .add_plan}, {@code tellHow}): when the library
     * already has the same plan (trigger, context and body; labels aside) it only gains the
     * source, as in Jason. {@return the plan in the library}
     */
    public Plan add(Plan p, Term source, boolean atBeginning) {
        Literal s = Literal.of("source", source);
        for (int i = 0; i < plans.size(); i++) {
            Plan known = plans.get(i);
            if (samePlan(known, p)) {
                Plan more = known.withLabel(known.label().addAnnot(s));
                plans.set(i, more);
                changed();
                return more;
            }
        }
        Literal label = p.label() == null ? Literal.atom("undefined") : p.label();
        return add(p.withLabel(label.addAnnot(s)), atBeginning);
    }

    private static boolean samePlan(Plan a, Plan b) {
        if (a.context() == null && b.context() != null || a.context() != null && b.context() != null && !a.context().equals(b.context())) {
            return false;
        }
        return a.trigger().equals(b.trigger()) && a.body().equals(b.body());
    }

    private Literal uniqueLabel() {
        while (true) {
            String l = "p__" + lastLabel.incrementAndGet();
            if (get(l) == null) {
                return Literal.atom(l);
            }
        }
    }

    public Plan get(String label) {
        for (Plan p : plans) {
            if (p.label().functor().equals(label)) {
                return p;
            }
        }
        return null;
    }

    public boolean remove(String label) {
        changed();
        return plans.removeIf(p -> p.label().functor().equals(label));
    }

    /**
     * Takes {@code source} away from the sources of the plan labelled {@code label}; the plan goes
     * when none is left. {@return whether there is such a plan}
     */
    public boolean removeSource(String label, Term source) {
        Plan p = get(label);
        if (p == null) {
            return false;
        }
        Literal s = Literal.of("source", source);
        if (p.label().annots().contains(s)) {
            Literal rest = p.label().withAnnots(p.label().annots().stream().filter(a -> !a.equals(s)).toList());
            if (rest.hasSource()) {
                plans.set(plans.indexOf(p), p.withLabel(rest));
                changed();
            } else {
                remove(label);
            }
        }
        return true;
    }

    /** The library changed: cached candidates go, and what callers derived from them is stale. */
    private void changed() {
        candidateCache.clear();
        last = null;
        before = null;
        Arrays.fill(byParts, null);
        version++;
    }

    /** {@return a number that changes whenever the plans change} */
    int version() {
        return version;
    }

    /** {@return the plans whose trigger may be relevant for {@code te} (same kind, functor, arity)} */
    public List<Plan> candidates(Trigger te) {
        if (!(te.literal() instanceof Literal l)) {
            return scan(te);
        }
        Last last = this.last;
        if (last != null && last.key.matches(te.op(), te.type(), l)) {
            return last.plans;
        }
        Last before = this.before;
        if (before != null && before.key.matches(te.op(), te.type(), l)) {
            this.before = last;
            this.last = before;
            return before.plans;
        }
        var key = new CandidateKey(te.op(), te.type(), l.functor(), l.arity(), l.negated(), l.ns());
        List<Plan> cached = candidateCache.get(key);
        if (cached == null) {
            cached = List.copyOf(scan(te));
            candidateCache.put(key, cached);
        }
        this.before = last;
        this.last = new Last(key, cached);
        return cached;
    }

    /**
     * The last two triggers' candidates: a loop of subgoals or a stream of messages asks for the
     * same ones every cycle (a -+b loop for those of -b and +b in turn).
     */
    private record Last(CandidateKey key, List<Plan> plans) {
    }

    /** A key with its own plans in each field, so that a look from another thread sees a pair that belongs together. */
    private Last last;
    private Last before;
    /**
     * The last answers of {@link #hasCandidate(Trigger.Op, Trigger.Type, Literal)}, one per slot of
     * the trigger's functor, operator and arity: a percept update asks for {@code -p} and
     * {@code +p} of every property that changed, so the last two answers never hold the next.
     */
    private final Last[] byParts = new Last[64];

    List<Plan> scan(Trigger te) { // package-private: ShortcutTest compares the caches with it
        var out = new ArrayList<Plan>();
        for (Plan p : plans) {
            if (isCandidate(p.trigger(), te)) {
                out.add(p);
            }
        }
        for (Plan p : kqmlPlans) {
            if (isCandidate(p.trigger(), te)) {
                out.add(p);
            }
        }
        return out;
    }

    /** Sets the plans that handle messages when the agent's own plans do not ({@code +!kqml_received}). */
    void setKqmlPlans(List<Plan> ps) {
        kqmlPlans = List.copyOf(ps);
        changed();
    }

    /** {@return whether p is one of the library's built-in message plans} */
    public boolean isKqmlPlan(Plan p) {
        for (int i = 0, n = kqmlPlans.size(); i < n; i++) {
            if (kqmlPlans.get(i) == p) {
                return true;
            }
        }
        return false;
    }

    public boolean hasCandidate(Trigger te) {
        return !candidates(te).isEmpty();
    }

    /**
     * As {@link #hasCandidate(Trigger)} for a trigger of these parts, made only when the last two
     * triggers' candidates do not answer (a told receiver asks for every message).
     */
    public boolean hasCandidate(Trigger.Op op, Trigger.Type type, Literal l) {
        Last last = this.last;
        if (last != null && last.key.matches(op, type, l)) {
            return !last.plans.isEmpty();
        }
        Last before = this.before;
        if (before != null && before.key.matches(op, type, l)) {
            return !before.plans.isEmpty();
        }
        int slot = (l.functor().hashCode() * 31 + op.ordinal() * 7 + l.arity()) & (byParts.length - 1);
        Last seen = byParts[slot];
        if (seen != null && seen.key.matches(op, type, l)) {
            return !seen.plans.isEmpty();
        }
        boolean has = hasCandidate(new Trigger(op, type, l));
        byParts[slot] = this.last; // the answer just made: candidates keeps it there
        return has;
    }

    private static boolean isCandidate(Trigger pt, Trigger te) {
        if (pt.op() != te.op() || pt.type() != te.type()) {
            return false;
        }
        if (!(pt.literal() instanceof Literal pl)) {
            return true; // a variable trigger, e.g. +!G
        }
        // a variable in the asked trigger ({+!_} for .relevant_plans) matches every plan
        if (!(te.literal() instanceof Literal el)) {
            return true;
        }
        // a variable namespace (+N::b, as a trigger or asked) stands for every namespace
        return pl.sameName(el) && (pl.ns() instanceof Var || el.ns() instanceof Var || Objects.equals(pl.ns(), el.ns()));
    }

    /** {@return whether a plan for goal-state meta-events ({@code ^!g}) was ever added} */
    public boolean hasGoalStatePlans() {
        return goalStatePlans;
    }

    /** {@return whether some plan reacts to the architecture's {@code jag_sleeping}, {@code jag_awaking}, ... events} */
    public boolean hasJagPlans() {
        return jagPlans;
    }

    public List<Plan> plans() {
        return plans;
    }
}
