package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.JasonHashOrder;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Renamer;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * {@code .intention(Id, State, Stack[, current])}: the agent's intentions, one solution each
 * (only the one running this action with {@code current}). Stack lists
 * {@code im(Label, {Trigger}, {Body}, Unifier)} from the top, as Jason.
 */
final class IntentionIa extends DefaultInternalAction {
    IntentionIa() {
        super(".intention", 2, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Circumstance c = ag.circumstance();
        boolean current = args.length == 4 && text(args[3]).equals("current");
        // in a plan's context (deliberation) the current intention is the selected event's
        Intention now = c.selectedIntention() != null ? c.selectedIntention()
                : c.selectedEvent() == null ? null : c.selectedEvent().intention();
        List<Intention> candidates = current ? (now == null ? List.of() : List.of(now)) : c.allIntentions();
        var out = new ArrayList<Unifier>();
        for (Intention i : candidates) {
            Unifier u = un.copy();
            if (!u.unifies(args[0], new NumberTerm(i.id()))) {
                continue;
            }
            if (!u.unifies(args[1], stateTerm(c, i))) {
                continue;
            }
            if (args.length >= 3 && !u.unifies(args[2], stack(i, ag))) {
                continue;
            }
            out.add(u);
        }
        return out.iterator();
    }

    /** The state, and for a waiting intention why, as Jason's: {@code waiting[reason(wait(3)[time(1500)])]}. */
    private static Term stateTerm(Circumstance c, Intention i) {
        String s = state(c, i);
        Literal reason = s.equals("waiting") ? c.waitingReason(i) : null;
        return reason == null ? Literal.atom(s) : Literal.atom(s).addAnnot(reason);
    }

    private static String state(Circumstance c, Intention i) {
        if (i == c.selectedIntention() || i.size() > 0 && c.selectedEvent() != null && c.selectedEvent().intention() == i || c.runningIntentions().contains(i)) {
            return "running";
        }
        return i.isSuspended() ? "suspended" : "waiting";
    }

    /**
     * The stack as Jason's {@code Intention.getAsTerm} makes it, top first: each body with fresh
     * variables, and each unifier as {@code map(Key, Value)} pairs in the order of Jason's hash map
     * of variable names, each key a fresh variable named after the one it stands for
     * ({@code _47ErrorId}), each value as bound: a variable stays the intention's own (a later
     * binding, as the failure plan's {@code X = failure}, shows through it) and the variables of a
     * structure are fresh. The trigger keeps the intention's variables.
     */
    static Term stack(Intention i, Agent ag) {
        var ims = new ArrayList<Term>();
        for (IntendedMeans im : i) {
            Unifier u = im.unifier();
            Literal label = im.plan().label() == null ? Literal.atom("undefined") : im.plan().label();
            if (im.plan().source() != null) {
                label = label.addAnnot(Literal.of("code_line", new NumberTerm(im.plan().source().line())))
                        .addAnnot(Literal.of("code_src", new StringTerm(im.plan().source().jasonFile())));
            }
            Term trigger = new TriggerTerm(im.trigger().withLiteral(u.apply(im.trigger().literal())));
            // the body as written (Jason does not apply the unifier; its variables come out fresh)
            Term body = Renamer.renameApart(new BodyTerm(new ArrayList<>(im.remainingSteps())), ag);
            var map = new ArrayList<Term>();
            for (Map.Entry<Var, Term> e : JasonHashOrder.of(u.bindings())) {
                // the value as bound, not evaluated again (it may hold plans with math.random in their bodies)
                Term value = e.getValue() instanceof Var ? e.getValue() : Renamer.renameApart(e.getValue(), ag);
                map.add(Literal.of("map", keyVar(e.getKey(), ag), value));
            }
            ims.add(Literal.of("im", label, trigger, body, listOf(map)));
        }
        return listOf(ims);
    }

    /** Jason's {@code UnnamedVar.create(name)}: {@code _47} for a one-letter name, else {@code _47Name}. */
    private static Var keyVar(Var v, Agent ag) {
        String name = JasonHashOrder.jasonName(v);
        Var fresh = ag.freshVar(v);
        return name.length() == 1 ? fresh : new Var(fresh + name);
    }
}
