package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.Map;

/** The bookkeeping shared by {@code .suspend}, {@code .resume} and {@code .suspended}. */
final class Suspensions {
    static final String SUSPENDED = "suspended-";
    static final String SELF_SUSPENDED = SUSPENDED + "self-";
    static final Literal REASON = Literal.atom("suspend_ia");

    private Suspensions() {
    }

    static boolean suspend(Agent ag, Literal g, Unifier un) {
        Circumstance c = ag.circumstance();
        Intention current = c.selectedIntention();
        if (g == null) {
            current.markSuspended(true);
            c.addPendingIntention(SELF_SUSPENDED + current.id(), REASON, current);
            ag.holdSelectedIntention();
            return true;
        }
        for (Map.Entry<String, Circumstance.Pending> p : c.pendingIntentions().entrySet()) {
            if (p.getValue().intention().hasGoal(g, un)) {
                p.getValue().intention().markSuspended(true);
            }
        }
        for (Intention i : c.runningIntentions()) {
            if (i.hasGoal(g, un)) {
                i.markSuspended(true);
                c.removeRunningIntention(i);
                c.addPendingIntention(SUSPENDED + i.id(), REASON, i);
            }
        }
        if (current != null && current.hasGoal(g, un)) {
            current.markSuspended(true);
            c.addPendingIntention(SELF_SUSPENDED + current.id(), REASON, current);
            ag.holdSelectedIntention();
        }
        return true;
    }

    static boolean resume(Agent ag, Literal g, Unifier un) {
        Circumstance c = ag.circumstance();
        for (Map.Entry<String, Circumstance.Pending> p : c.pendingIntentions().entrySet()) {
            Intention i = p.getValue().intention();
            String key = p.getKey();
            if (i.isSuspended() && i.hasGoal(g, un)) {
                i.markSuspended(false);
                if (key.startsWith(SUSPENDED)) {
                    c.removePendingIntention(key);
                    if (key.startsWith(SELF_SUSPENDED)) {
                        i.peek().removeCurrentStep();
                    }
                    c.addRunningIntention(i);
                }
            }
        }
        return true;
    }

    static boolean suspended(Agent ag, Literal g, Term reason, Unifier un) {
        for (Map.Entry<String, Circumstance.Pending> p : ag.circumstance().pendingIntentions().entrySet()) {
            if (p.getValue().intention().hasGoal(g, un)) {
                Term r = p.getValue().reason() == null ? new StringTerm(p.getKey()) : p.getValue().reason();
                return un.unifies(reason, r);
            }
        }
        return false;
    }
}
