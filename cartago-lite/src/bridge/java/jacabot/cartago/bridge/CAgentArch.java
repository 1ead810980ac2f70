package jacabot.cartago.bridge;

import jacabot.agent.runtime.Environment;
import jacabot.agent.runtime.LocalArch;
import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserver;
import jacabot.cartago.PropertySnapshot;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Consumer;

/**
 * JaCa's {@code c4jason.CAgentArch}: the agent perceives the artifacts it focuses. Each
 * observable property {@code p(v)} is a belief
 * {@code p(v)[artifact_id(Id), artifact_name(Name), artifact_name(Id, Name), percept_type(obs_prop), source(percept)]};
 * each signal {@code s(a)} is a {@code +s(a)[..., percept_type(obs_ev)]} event that is never
 * stored. Changes are queued by the artifacts' threads and applied at the start of the agent's
 * next reasoning cycle, so they arrive at deterministic points.
 */
public class CAgentArch extends LocalArch {
    private final ConcurrentLinkedQueue<Consumer<Agent>> pending = new ConcurrentLinkedQueue<>();
    /** The beliefs the focused properties became, by artifact. */
    private final Map<ArtifactId, List<Literal>> beliefs = new HashMap<>();
    /** {@code current_wsp(Id, Name, Node)} and {@code joinedWsp(Id, Name, FullName)} as believed now. */
    private final Set<Literal> workspaceBeliefs = new HashSet<>();
    private final AgentSession session;
    private final CartagoLibrary library;
    private boolean libraryInstalled;

    public CAgentArch(LocalArch local) {
        super(local.mas(), local.name());
        Environment env = local.mas().environment();
        if (!(env instanceof CartagoEnvironment cartago)) {
            throw new IllegalStateException("agentArchClass jacabot.cartago.bridge.CAgentArch needs "
                    + "environment: jacabot.cartago.bridge.CartagoEnvironment");
        }
        session = cartago.session(local.name(), new Observer());
        session.setListener(s -> queue(this::syncWorkspaceBeliefs));
        library = new CartagoLibrary(cartago, session);
    }

    @Override
    public void sense(Agent agent) {
        if (!libraryInstalled) {
            library.install(agent);
            libraryInstalled = true;
        }
        Consumer<Agent> change;
        while ((change = pending.poll()) != null) {
            change.accept(agent);
        }
    }

    @Override
    public boolean canSleep() {
        return pending.isEmpty();
    }

    private void queue(Consumer<Agent> change) {
        pending.add(change);
        wake();
    }

    /**
     * Brings {@code current_wsp(WspId, Name, Node)} (CArtAgO 2's belief, which its examples use) and
     * {@code joinedWsp(WspId, Name, FullName)} (CArtAgO 3's percept, one per joined workspace) up to date.
     */
    private void syncWorkspaceBeliefs(Agent ag) {
        var now = new LinkedHashSet<Literal>();
        session.current().ifPresent(w -> now.add(new Literal("current_wsp", List.of(TermConverter.toTerm(w.id()),
                new StringTerm(w.id().name()), new StringTerm(w.id().node())), List.of(Literal.SOURCE_PERCEPT), false)));
        for (JoinedWorkspace w : session.all()) {
            now.add(new Literal("joinedWsp", List.of(TermConverter.toTerm(w.id()), new StringTerm(w.id().name()),
                    new StringTerm(w.id().getFullName())), List.of(Literal.SOURCE_PERCEPT), false));
        }
        for (var it = workspaceBeliefs.iterator(); it.hasNext();) {
            Literal l = it.next();
            if (!now.contains(l)) {
                ag.removePercept(l);
                it.remove();
            }
        }
        for (Literal l : now) {
            if (workspaceBeliefs.add(l)) {
                ag.addPercept(l);
            }
        }
    }

    private static List<Term> annots(ArtifactId id, String type) {
        var a = new ArrayList<Term>();
        Term idTerm = TermConverter.toTerm(id);
        a.add(Literal.of("artifact_id", idTerm));
        a.add(Literal.of("artifact_name", new StringTerm(id.name())));
        a.add(Literal.of("artifact_name", idTerm, new StringTerm(id.name())));
        a.add(Literal.of("percept_type", Literal.atom(type)));
        a.add(Literal.SOURCE_PERCEPT);
        return a;
    }

    /** The annotations of each artifact's property beliefs, made once (used on the agent's thread only, in sense). */
    private final Map<ArtifactId, List<Term>> propertyAnnots = new HashMap<>();
    /** The annotations of each artifact's signals, sorted once (used on the agent's thread only, in sense). */
    private final Map<ArtifactId, List<Term>> signalAnnots = new HashMap<>();
    /** The last artifact {@link #belief} served, and its annotations: nearly every change comes from one artifact. */
    private ArtifactId lastId;
    private List<Term> lastAnnots;

    private Literal belief(ArtifactId id, PropertySnapshot p) {
        if (id != lastId) {
            // checked sorted once, so each literal keeps the list as it is
            lastAnnots = propertyAnnots.computeIfAbsent(id, k -> Literal.presortedAnnots(annots(k, "obs_prop")));
            lastId = id;
        }
        return new Literal(p.name(), TermConverter.toTerms(p.values()), lastAnnots, false);
    }

    private void add(Agent ag, ArtifactId id, PropertySnapshot p) {
        Literal l = belief(id, p);
        beliefs.computeIfAbsent(id, k -> new ArrayList<>()).add(l);
        ag.addPercept(l);
    }

    /**
     * Removes the belief of one property (several may share a name: the values tell them apart).
     */
    private void remove(Agent ag, ArtifactId id, PropertySnapshot p) {
        List<Literal> of = beliefsOf(id);
        int k = indexOf(of, p);
        if (k >= 0) {
            ag.removePercept(of.remove(k));
        }
    }

    /**
     * A property's new value: as {@link #remove} of the old then {@link #add} of the new, with the
     * same events in the same order, and the belief replaced in one step of the belief base where
     * it is the only belief of its predicate (the usual case: {@code BeliefBase.replace}).
     */
    private void update(Agent ag, ArtifactId id, PropertySnapshot old, PropertySnapshot now) {
        List<Literal> of = beliefsOf(id);
        int k = indexOf(of, old);
        Literal l = belief(id, now);
        if (k >= 0 && ag.beliefBase().replace(of.get(k), l)) {
            // the beliefs of a name and values are equal, so the list's order among them does not matter
            Literal gone = of.set(k, l);
            ag.circumstance().addBeliefEvent(Trigger.Op.DEL, gone);
            ag.circumstance().addBeliefEvent(Trigger.Op.ADD, l);
            return;
        }
        if (k >= 0) {
            ag.removePercept(of.remove(k));
        }
        beliefs.computeIfAbsent(id, x -> new ArrayList<>()).add(l);
        ag.addPercept(l);
    }

    /** The last artifact whose belief list {@link #beliefsOf} found, and the list (a list, once made, stays the artifact's). */
    private ArtifactId lastListId;
    private List<Literal> lastList;

    private List<Literal> beliefsOf(ArtifactId id) {
        if (id != lastListId) {
            lastList = beliefs.get(id);
            lastListId = lastList == null ? null : id;
        }
        return lastList;
    }

    /**
     * {@return where the belief of property {@code p} is among the artifact's, or -1} It is found by
     * name and arguments: all carry the same annotations, so it need not be made anew to be compared.
     */
    private static int indexOf(List<Literal> of, PropertySnapshot p) {
        if (of == null) {
            return -1;
        }
        List<Term> args = null;
        for (int k = 0, n = of.size(); k < n; k++) {
            Literal l = of.get(k);
            if (l.functor().equals(p.name()) && l.arity() == p.values().size()) {
                if (args == null) {
                    args = TermConverter.toTerms(p.values());
                }
                if (l.args().equals(args)) {
                    return k;
                }
            }
        }
        return -1;
    }

    /** Receives the workspace's notifications on artifact threads and queues them. */
    private final class Observer implements ArtifactObserver {
        @Override
        public void focused(ArtifactId artifact, List<PropertySnapshot> properties) {
            queue(ag -> properties.forEach(p -> add(ag, artifact, p)));
        }

        @Override
        public void propertyAdded(ArtifactId artifact, PropertySnapshot property) {
            queue(ag -> add(ag, artifact, property));
        }

        @Override
        public void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue) {
            queue(ag -> update(ag, artifact, oldValue, newValue));
        }

        @Override
        public void propertyRemoved(ArtifactId artifact, PropertySnapshot property) {
            queue(ag -> remove(ag, artifact, property));
        }

        @Override
        public void signalled(ArtifactId artifact, String type, List<Object> args) {
            queue(ag -> ag.addExternalEvent(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF,
                    new Literal(type, TermConverter.toTerms(args), signalAnnots.computeIfAbsent(artifact,
                            k -> Literal.presortedAnnots(annots(k, "obs_ev"))), false))));
        }

        @Override
        public void focusEnded(ArtifactId artifact, List<PropertySnapshot> properties, boolean disposed) {
            queue(ag -> {
                properties.forEach(p -> remove(ag, artifact, p));
                propertyAnnots.remove(artifact);
                signalAnnots.remove(artifact);
                lastId = null;
            });
        }
    }
}
