package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.IntendedMeans;
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
            if (args.length >= 3 && !u.unifies(args[2], Renamer.renameApart(stack(i), ag))) {
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

    static Term stack(Intention i) {
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
            var steps = new ArrayList<>(im.remainingSteps());
            var map = new ArrayList<Term>();
            for (Map.Entry<Var, Term> e : u.bindings().entrySet()) {
                // the value as bound, not evaluated again (it may hold plans with math.random in their bodies)
                map.add(Literal.of("map", e.getKey(), e.getValue()));
            }
            ims.add(Literal.of("im", label, trigger, new BodyTerm(steps), listOf(map)));
        }
        return listOf(ims);
    }
}
