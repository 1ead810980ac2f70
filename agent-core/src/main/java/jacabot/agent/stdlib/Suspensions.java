package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.GoalStates;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/** The bookkeeping shared by {@code .suspend}, {@code .resume} and {@code .suspended}. */
final class Suspensions {
    static final String SUSPENDED = "suspended-";
    static final String SELF_SUSPENDED = SUSPENDED + "self-";
    static final Literal REASON = Literal.atom("suspend_ia");
    static final Literal RESUME_REASON = Literal.atom("resume_ia");

    private Suspensions() {
    }

    static boolean suspend(Agent ag, Literal g, Unifier un) {
        Circumstance c = ag.circumstance();
        Intention current = c.selectedIntention();
        GoalStates gs = ag.goalStates();
        if (g == null) {
            current.markSuspended(true);
            c.addPendingIntention(SELF_SUSPENDED + current.id(), REASON, current);
            gs.ofTop(current, GoalStates.State.suspended, REASON);
            ag.holdSelectedIntention();
            return true;
        }
        for (Map.Entry<String, Circumstance.Pending> p : c.pendingIntentions().entrySet()) {
            if (p.getValue().intention().hasGoal(g, un)) {
                p.getValue().intention().markSuspended(true);
                gs.post(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, g), GoalStates.State.suspended, REASON);
            }
        }
        for (Intention i : c.runningIntentions()) {
            if (i.hasGoal(g, un)) {
                i.markSuspended(true);
                c.removeRunningIntention(i);
                c.addPendingIntention(SUSPENDED + i.id(), REASON, i);
                gs.ofTop(i, GoalStates.State.suspended, REASON);
            }
        }
        if (current != null && current.hasGoal(g, un)) {
            current.markSuspended(true);
            c.addPendingIntention(SELF_SUSPENDED + current.id(), REASON, current);
            gs.ofTop(current, GoalStates.State.suspended, REASON);
            ag.holdSelectedIntention();
        }
        // goals not yet intended (still events, as after !!g) wait in PE
        Trigger asked = new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, g);
        int n = 0;
        for (Event e : c.eventList()) {
            Intention i = e.intention();
            if (matches(e, asked, un)) {
                c.removeEvent(e);
                c.addPendingEvent(SUSPENDED + e.trigger() + (n++), e);
                if (i != null) {
                    i.markSuspended(true);
                }
                gs.post(e.trigger(), GoalStates.State.suspended, REASON);
            }
        }
        return true;
    }

    private static boolean matches(Event e, Trigger asked, Unifier un) {
        Trigger t = e.trigger();
        return t.op() == asked.op() && t.type() == asked.type() && un.copy().unifies(asked.literal(), t.literal())
                || e.intention() != null && e.intention().hasGoal((Literal) asked.literal(), un);
    }

    static boolean resume(Agent ag, Literal g, Unifier un) {
        Circumstance c = ag.circumstance();
        Trigger asked = new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, g);
        for (Map.Entry<String, Event> p : c.pendingEvents().entrySet()) {
            Event e = p.getValue();
            if (p.getKey().startsWith(SUSPENDED) && matches(e, asked, un)) {
                c.removePendingEvent(p.getKey());
                if (e.intention() == null) {
                    ag.goalStates().post(e.trigger(), GoalStates.State.resumed, RESUME_REASON);
                } else {
                    ag.goalStates().ofTop(e.intention(), GoalStates.State.resumed, RESUME_REASON);
                }
                c.addEvent(e);
                if (e.intention() != null) {
                    e.intention().markSuspended(false);
                }
            }
        }
        Map<String, Circumstance.Pending> pending = c.pendingIntentions();
        for (String key : inJasonOrder(pending.keySet())) {
            Circumstance.Pending p = pending.get(key);
            Intention i = p.intention();
            // as Jason's, the pattern is unified in the caller's unifier: the first intention that
            // matches binds its variables, so .resume(g(_)) resumes one of several g goals
            if (i.isSuspended() && i.hasGoal(g, un) && i.hasGoalBinding(g, un)) {
                i.markSuspended(false);
                GoalStates gs = ag.goalStates();
                gs.ofTop(i, GoalStates.State.resumed, RESUME_REASON);
                if (key.startsWith(SUSPENDED)) {
                    gs.ofTop(i, GoalStates.State.executing, null);
                    c.removePendingIntention(key);
                    if (key.startsWith(SELF_SUSPENDED)) {
                        i.peek().removeCurrentStep();
                    }
                    c.addRunningIntention(i);
                } else {
                    gs.ofTop(i, GoalStates.State.waiting, p.reason());
                }
            }
        }
        return true;
    }

    /**
     * {@return the keys in the order Jason 3.2 visits its pending intentions: a ConcurrentHashMap
     * keyed by the same names, so that which of several suspended goals resumes first is Jason's}
     */
    private static List<String> inJasonOrder(Set<String> keys) {
        var jasonPI = new ConcurrentHashMap<String, Boolean>();
        for (String k : keys) {
            jasonPI.put(k, Boolean.TRUE);
        }
        return new ArrayList<>(jasonPI.keySet());
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
