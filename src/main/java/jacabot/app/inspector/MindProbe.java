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
    /** The beliefs and intentions as the last capture printed them (captures run on the agent's thread). */
    private final BeliefTexts beliefs = new BeliefTexts();
    private final IntentionTexts intentions = new IntentionTexts();
    private List<String> lastEvents = List.of();

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
                top.trigger().toString(), intentions.headOf(top.plan()), top.unifier().toString()));
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
        Circumstance c = agent.circumstance();
        var events = new ArrayList<String>();
        for (Event e : c.eventList()) {
            events.add(e.trigger().toString() + (e.isExternal() ? "" : "  (intention " + e.intention().id() + ")"));
        }
        if (!events.equals(lastEvents)) {
            lastEvents = List.copyOf(events);
        }
        return new MindState(agent.name(), number, agent.clock().millis(), cyclesDone, beliefs.of(agent.beliefBase()),
                lastEvents, intentions.of(c), chosen);
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

}
