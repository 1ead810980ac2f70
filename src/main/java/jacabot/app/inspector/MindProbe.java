package jacabot.app.inspector;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.CircumstanceListener;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Intention;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.WeakHashMap;

/**
 * Reads one agent's mind into {@link MindState}s. Read-only: it never changes the agent, so a
 * lockstep run stays the same with or without it. Every method runs on the agent's own thread
 * (the one running its reasoning cycles), which is what makes a state whole: either between two
 * cycles ({@link #capture}) or inside one, where Jason's AddIM pushes a new intended means
 * ({@link CircumstanceListener#intentionAdded}, kept as a {@link MindState.Selection}).
 */
public final class MindProbe {
    /** At most this many selections wait between two captures (a busy agent cannot fill memory). */
    static final int MAX_PENDING_SELECTIONS = 200;

    private final Agent agent;
    /** Intended means already reported: a new top of an intention is a plan just selected (AddIM). */
    private final Set<IntendedMeans> seen = Collections.newSetFromMap(new WeakHashMap<>());
    private final List<MindState.Selection> selections = new ArrayList<>();
    private long seq;
    private int planCount = -1;
    private List<String> plans = List.of();
    private List<Plan> planObjects = List.of();
    /** The facts the last capture showed, by identity (captures run on the agent's thread). */
    private IdentityHashMap<Literal, MindState.Belief> lastShown = new IdentityHashMap<>();

    private MindProbe(Agent agent) {
        this.agent = agent;
    }

    /**
     * Attaches a probe. Call it before the agent runs, or on its thread: the circumstance's
     * listener list is the agent's own.
     */
    public static MindProbe attach(Agent agent) {
        MindProbe probe = new MindProbe(agent);
        agent.circumstance().addListener(new CircumstanceListener() {
            @Override
            public void intentionAdded(Intention i) {
                probe.noteTop(i);
            }

            @Override
            public boolean hearsBeliefEvent(Trigger.Op op, Literal b) {
                return false; // it reads intentions only: percepts no plan is for stay unmade, as without it
            }
        });
        return probe;
    }

    public String agentName() {
        return agent.name();
    }

    private void noteTop(Intention i) {
        IntendedMeans top = i.peek();
        if (top == null || !seen.add(top)) {
            return;
        }
        if (selections.size() >= MAX_PENDING_SELECTIONS) {
            selections.remove(0);
        }
        // the unifier now is the one that made the plan applicable (its body has not run yet)
        selections.add(new MindState.Selection(agent.clock().millis(), agent.cycles(), i.id(),
                top.trigger().toString(), planHead(top.plan()), top.unifier().toString()));
    }

    /** {@return the mind now; call between two reasoning cycles, on the agent's thread} */
    public MindState capture() {
        var chosen = List.copyOf(selections);
        selections.clear();
        return state(++seq, agent.cycles(), chosen);
    }

    /**
     * {@return the mind now, without taking the selections since the last capture (they stay for
     * it: a step log written with peeks between is the same)}; at the start of a reasoning cycle,
     * on the agent's thread
     *
     * @param cyclesDone the cycles run so far (the agent counts the one starting)
     */
    public MindState peek(long cyclesDone) {
        return state(seq, cyclesDone, List.copyOf(selections));
    }

    private MindState state(long number, long cyclesDone, List<MindState.Selection> chosen) {
        var beliefs = new ArrayList<MindState.Belief>();
        var shown = new IdentityHashMap<Literal, MindState.Belief>();
        for (BeliefBase.Entry e : agent.beliefBase().all()) {
            // rules too, as Jason's inspector lists them with the facts
            if (e.rule() != null) {
                beliefs.add(new MindState.Belief(e.rule().toString(), List.of(), List.of()));
                continue;
            }
            // a fact is an immutable literal: one the last capture showed is shown the same
            MindState.Belief b = lastShown.get(e.literal());
            if (b == null) {
                b = belief(e.literal());
            }
            if (printsTheSame(e.literal())) {
                shown.put(e.literal(), b);
            }
            beliefs.add(b);
        }
        lastShown = shown;
        Circumstance c = agent.circumstance();
        var events = new ArrayList<String>();
        for (Event e : c.eventList()) {
            events.add(e.trigger().toString() + (e.isExternal() ? "" : "  (intention " + e.intention().id() + ")"));
        }
        var pendingReason = new HashMap<Intention, String>();
        for (Map.Entry<String, Circumstance.Pending> p : c.pendingIntentions().entrySet()) {
            pendingReason.put(p.getValue().intention(), "waiting: " + p.getValue().reason());
        }
        var intentions = new ArrayList<MindState.IntentionView>();
        for (Intention i : c.allIntentions()) {
            var stack = new ArrayList<MindState.Means>();
            for (IntendedMeans im : i) {
                stack.add(means(im));
            }
            String state = pendingReason.getOrDefault(i,
                    i.isSuspended() ? "suspended" : c.hasRunningIntention(i) ? "running" : "waiting");
            intentions.add(new MindState.IntentionView(i.id(), state, stack));
        }
        intentions.sort(Comparator.comparingInt(MindState.IntentionView::id));
        return new MindState(agent.name(), number, agent.clock().millis(), cyclesDone, beliefs, events, intentions, chosen);
    }

    /** {@return the plan library as text, re-read only when its size changes (.add_plan, .remove_plan)} */
    public List<String> plans() {
        List<Plan> now = agent.planLibrary().plans();
        if (now.size() != planCount || !samePlans(now)) {
            plans = planTexts(now);
            planObjects = List.copyOf(now);
            planCount = now.size();
        }
        return plans;
    }

    /** {@return whether the library holds the same plans as when last read (a reload may keep their number)} */
    private boolean samePlans(List<Plan> now) {
        for (int i = 0; i < now.size(); i++) {
            if (now.get(i) != planObjects.get(i)) {
                return false;
            }
        }
        return true;
    }

    /** {@return an agent's plan library as the page shows it: each plan, and where it was written} */
    public static List<String> planTexts(Agent agent) {
        return planTexts(agent.planLibrary().plans());
    }

    private static List<String> planTexts(List<Plan> library) {
        var out = new ArrayList<String>();
        for (Plan p : library) {
            String where = p.source() == null || p.source().line() == 0 ? "" : "   // " + p.source();
            out.add(withoutSourceAnnots(p) + where);
        }
        return List.copyOf(out);
    }

    private static String withoutSourceAnnots(Plan p) {
        return p.label() == null ? p.toString() : p.withLabel(p.label().withoutAnnots()).toString();
    }

    /**
     * {@return whether the literal's text cannot change: made of literals, numbers, strings, lists
     * and variables only} (an object term prints its Java object, which may change)
     */
    private static boolean printsTheSame(Term t) {
        if (t instanceof Literal l) {
            for (Term a : l.args()) {
                if (!printsTheSame(a)) {
                    return false;
                }
            }
            for (Term a : l.annots()) {
                if (!printsTheSame(a)) {
                    return false;
                }
            }
            return true;
        }
        if (t instanceof ListTerm.Cons c) {
            return printsTheSame(c.head()) && printsTheSame(c.tail());
        }
        return t instanceof NumberTerm || t instanceof StringTerm || t instanceof ListTerm.Empty || t instanceof Var;
    }

    static MindState.Belief belief(Literal l) {
        var sources = new ArrayList<String>();
        var annots = new ArrayList<String>();
        for (Term a : l.annots()) {
            if (a instanceof Literal s && s.functor().equals("source") && s.arity() == 1) {
                sources.add(s.arg(0).toString());
            } else {
                annots.add(a.toString());
            }
        }
        return new MindState.Belief(l.withoutAnnots().toString(), sources, annots);
    }

    private static MindState.Means means(IntendedMeans im) {
        String current = im.currentStep() == null ? "" : im.currentStep().toString();
        String all = im.remainingBody();
        String rest = all.startsWith(current) ? all.substring(current.length()).replaceFirst("^;\\s*", "") : all;
        return new MindState.Means(im.trigger().toString(), planHead(im.plan()), im.unifier().toString(), current, rest);
    }

    /** {@return {@code @label +trigger : context}, the plan without its body} */
    static String planHead(Plan p) {
        var out = new StringBuilder();
        if (p.label() != null) {
            out.append('@').append(p.label().withoutAnnots()).append(' ');
        }
        out.append(p.trigger());
        if (p.context() != null) {
            out.append(" : ").append(p.context());
        }
        return out.toString();
    }
}
