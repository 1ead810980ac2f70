package jacabot.agent.semantics;

import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * Jason's reasoning cycle: sense (ProcMsg), deliberate (SelEv, FindOp, AddIM) and act (ProcAct,
 * SelInt, ExecInt, ClrInt). Each rule is a method named after it; plan-body formulas are run by
 * {@link BodyExecutor}.
 */
final class ReasoningCycle {
    /** The most intended means an intention may hold before a new subgoal fails (system property jacabot.maxIntentionDepth). */
    static final int MAX_INTENTION_DEPTH = Integer.getInteger("jacabot.maxIntentionDepth", 10_000);
    private final Agent ag;
    private final Circumstance c;
    private final BodyExecutor exec;
    private final MessageHandler messages;
    private final IntendedMeans.Start start = new IntendedMeans.Start();
    private boolean selectedDropped;
    private boolean selectedHeld;
    /** The intention {@link #holdForFailureEvent} kept out of I last; identity only, never run from here. */
    private Intention heldForFailureEvent;
    /** Whether a cycle ran: the first reports the internal actions the agent does not know. */
    private boolean started;

    ReasoningCycle(Agent ag) {
        this.ag = ag;
        this.c = ag.circumstance();
        this.exec = new BodyExecutor(ag, this);
        this.messages = new MessageHandler(ag, this);
    }

    void run() {
        sense();
        if (!started) {
            // after the first sense: an architecture adds its libraries' actions there (JaCa's cartago.*)
            started = true;
            UnknownActions.report(ag);
        }
        if (ag.isStopped()) {
            return;
        }
        deliberate();
        if (ag.isStopped()) {
            return;
        }
        act();
    }

    // ---- sense --------------------------------------------------------------------------------

    private void sense() {
        ag.fireDueTimers();
        ag.arch().sense(ag);
        List<Literal> percepts = ag.arch().perceive();
        if (percepts != null) {
            ag.beliefUpdate(percepts);
        }
        ag.senseIdleness();
        applyProcMsg();
    }

    /** ProcMsg: handle one message of the mailbox. */
    private void applyProcMsg() {
        Message m = c.pollMessage();
        if (m != null) {
            messages.handle(m);
        }
    }

    // ---- deliberate ---------------------------------------------------------------------------

    private void deliberate() {
        ag.runBeginOfCycleTasks();
        c.setSelectedEvent(null);
        while (true) {
            // SelEv
            if (c.hasAtomicIntention()) {
                return;
            }
            Event se = c.pollAtomicEvent();
            if (se == null) {
                se = c.events().poll();
            }
            if (se == null) {
                return;
            }
            c.setSelectedEvent(se);
            try {
                if (applyFindOp(se)) {
                    return;
                }
            } catch (StackOverflowError e) {
                ag.warn("The context of a plan for " + se.trigger() + " recursed too deep: the event is dropped");
                if (se.intention() != null) {
                    ag.dropIntention(se.intention());
                }
                return;
            }
            // an irrelevant external event is discarded and another one selected
        }
    }

    /**
     * FindOp (and AddIM): the first applicable plan, in file order, with its first unifier.
     * {@return whether deliberation is over for this cycle}
     */
    private boolean applyFindOp(Event se) {
        Unifier u = null;
        // a message no plan of the agent's own handles gets the default handling (Jason's kqmlPlans)
        boolean message = se.isExternal() && se.trigger().isAchieveGoal() && se.trigger().isAddition()
                && se.trigger().literal() instanceof Literal l && l.arity() == 4 && l.functor().equals("kqml_received");
        List<Plan> candidates = ag.planLibrary().candidates(se.trigger());
        Term eventFirst = firstArg(se.trigger().literal());
        for (int k = 0, n = candidates.size(); k < n; k++) {
            Plan p = candidates.get(k);
            if (message && ag.planLibrary().isKqmlPlan(p)) {
                message = false;
                if (messages.handleByDefault((Literal) se.trigger().literal())) {
                    return true;
                }
            }
            // a plan not taken leaves the unifier to the next one: a failed unification or
            // context bound nothing
            if (u == null) {
                u = ag.newUnifier();
            } else {
                u.undoTo(0);
            }
            if (!isRelevant(p.trigger(), se.trigger(), eventFirst, u)) {
                continue;
            }
            // the context's first solution is made in the plan's own unifier; a context that fails
            // leaves it as it was
            if (p.context() != null && (ag.solver().failsAtFirstComparison(p.context(), u)
                    || !ag.solver().believesContext(p.context(), u))) {
                continue;
            }
            applyAddIM(se, p, u);
            return true;
        }
        if (message && messages.handleByDefault((Literal) se.trigger().literal())) {
            return true;
        }
        // Jason's: "applicable" once a plan of the trigger's kind, functor and arity exists (error(no_applicable))
        return applyRelApplPlRule2(se, candidates.isEmpty() ? "relevant" : "applicable");
    }

    /** {@code eventFirst}: the event literal's {@link #firstArg}, found once for all the candidates */
    private static boolean isRelevant(Trigger planTrigger, Trigger event, Term eventFirst, Unifier u) {
        return planTrigger.op() == event.op() && planTrigger.type() == event.type()
                && (eventFirst == null || !firstArgsDiffer(planTrigger.literal(), eventFirst))
                && u.unifies(planTrigger.literal(), event.literal());
    }

    /** {@return the first argument of a literal, or null} */
    private static Term firstArg(Term t) {
        return t instanceof Literal l && l.arity() > 0 ? l.arg(0) : null;
    }

    /**
     * {@return whether the plan's literal and the event's have as first argument a number, or a
     * plain atom, and not the same} They cannot unify then: {@code +!count(200000)} is tried for
     * every {@code !count(N)} of a loop, and this answers without the unifier.
     */
    private static boolean firstArgsDiffer(Term a, Term y) {
        if (!(a instanceof Literal la) || la.arity() == 0) {
            return false;
        }
        Term x = la.arg(0);
        if (x instanceof NumberTerm nx) {
            return y instanceof NumberTerm ny && nx.value() != ny.value();
        }
        return x instanceof Literal ax && y instanceof Literal ay && ax.isAtom() && ay.isAtom() && ax.ns() == null
                && ay.ns() == null && !ax.functor().equals(ay.functor());
    }

    /** No relevant or applicable plan: goals fail, internal events go on, external ones are dropped. */
    private boolean applyRelApplPlRule2(Event se, String what) {
        Trigger te = se.trigger();
        if (te.isGoal() && te.op() != Trigger.Op.GOAL_STATE) {
            String msg = "Found a goal for which there is no " + what + " plan: " + te;
            if (!generateGoalDeletionFromEvent(se, errorAnnots("no_" + what, msg))) {
                ag.warn(msg);
            }
            return true;
        }
        if (!se.isExternal()) {
            Intention i = se.intention();
            joinRenamedVars(i.peek(), i.peek().unifier());
            removeActionReQueue(i);
            return true;
        }
        return false;
    }

    /** AddIM: a new intention for an external event, or a new top of the event's intention. */
    private void applyAddIM(Event se, Plan p, Unifier u) {
        if (se.intention() != null && se.intention() == heldForFailureEvent) {
            heldForFailureEvent = null; // its failure plan runs: a later unhandled failure drops it
        }
        if (!se.isExternal() && se.trigger().isAddition() && se.intention().size() >= MAX_INTENTION_DEPTH) {
            // runaway goal recursion fails the goal instead of filling the heap (Jason would grow on)
            generateGoalDeletionFromEvent(se, errorAnnots("stack_overflow", "the intention holds " + se.intention().size()
                    + " intended means, the limit (-Djacabot.maxIntentionDepth)"));
            return;
        }
        if (ag.planListener() != null) {
            ag.planListener().planSelected(se, p);
        }
        IntendedMeans im = start.of(p, se.trigger(), u);
        if (se.trigger().isAchieveGoal() && se.trigger().isAddition()) {
            ag.goalStates().post(se.trigger(), GoalStates.State.executing, null);
        }
        if (se.isExternal()) {
            Intention i = new Intention(ag.nextIntentionId());
            i.push(im);
            c.addRunningIntention(i);
            return;
        }
        Intention i = se.intention();
        IntendedMeans top = i.peek();
        // tail recursion optimisation: !g as the last step of a plan for g replaces that plan
        if (top != null && top.trigger().isAddition() && im.trigger().isAddition()
                && top.trigger().isGoal() && im.trigger().isGoal() && top.isLastStep()
                && samePredicate(top.trigger(), im.trigger())) {
            if (ag.goalStates().listening()) {
                ag.goalStates().finished(GoalStates.of(top), GoalStates.State.achieved);
            }
            i.pop();
            IntendedMeans base = i.peek();
            if (base != null && base.renamedVars() != null) {
                for (Map.Entry<Var, Var> e : base.renamedVars().entrySet()) {
                    Term value = top.unifier().deref(e.getValue());
                    if (value instanceof Var w) {
                        Var again = top.renamedVarFor(w);
                        if (again != null) {
                            e.setValue(again);
                        }
                    } else {
                        im.unifier().bind(e.getValue(), top.unifier().apply(value));
                    }
                }
            }
        }
        i.push(im);
        c.addRunningIntention(i);
    }

    private static boolean samePredicate(Trigger a, Trigger b) {
        return a.literal() instanceof Literal la && b.literal() instanceof Literal lb
                && la.functor().equals(lb.functor()) && la.arity() == lb.arity() && Objects.equals(la.ns(), lb.ns());
    }

    // ---- act ----------------------------------------------------------------------------------

    private void act() {
        applyProcAct();
        Intention si = applySelInt();
        if (si == null) {
            return;
        }
        c.setSelectedIntention(si);
        selectedDropped = false;
        selectedHeld = false;
        try {
            exec.execute(si);
        } catch (StackOverflowError e) {
            // a too deep recursion (rules, terms) fails the intention, not the agent's thread
            generateGoalDeletion(si, errorAnnots("stack_overflow", "the recursion went too deep"));
        }
        c.setSelectedIntention(null);
        if (!selectedDropped) {
            applyClrInt(si);
        }
        ActionExec a = c.action();
        c.setAction(null);
        if (a != null && !selectedDropped) {
            c.addPendingAction(a);
            ag.arch().act(a, ag);
        }
    }

    /** ProcAct: handle the feedback of one executed action; the cycle goes on to SelInt (as Jason). */
    private void applyProcAct() {
        if (c.hasIntentionWithGoalCondition()) {
            GoalDropper.dropSatisfied(ag);
        }
        ActionExec a;
        while ((a = c.pollFeedbackAction()) != null) {
            Intention i = a.intention();
            if (c.removePendingAction(i.id()) == null) {
                continue; // the intention was dropped meanwhile
            }
            if (a.result()) {
                if (a.outputs() != null) {
                    Unifier u = i.peek().unifier();
                    for (Map.Entry<Var, Term> e : a.outputs().bindings().entrySet()) {
                        u.unifies(e.getKey(), e.getValue());
                    }
                }
                removeActionReQueue(i);
                applyClrInt(i);
            } else {
                var annots = errorAnnots("action_failed", a.failureMessage() == null ? "" : a.failureMessage());
                annots.addAll(a.failureReason());
                generateGoalDeletion(i, annots);
            }
            break;
        }
    }

    /** SelInt: the atomic intention if any, else the first running one (round robin). */
    private Intention applySelInt() {
        Intention i = c.takeAtomicIntention();
        if (i != null) {
            return i;
        }
        if (c.isAtomicIntentionSuspended()) {
            return null;
        }
        return c.pollRunningIntention();
    }

    void dropSelected() {
        selectedDropped = true;
    }

    /** Keeps the selected intention out of I after its current internal action. */
    void holdSelected() {
        selectedHeld = true;
    }

    /** {@link #holdSelected} for a {@code .fail_goal}'s own failure event: with no failure plan
     *  applying, back to I (Jason's stays there) */
    void holdForFailureEvent(Intention i) {
        holdSelected();
        heldForFailureEvent = i;
    }

    boolean isSelectedHeld() {
        return selectedHeld || selectedDropped;
    }

    /** Removes the step just done and puts the intention back at the end of I. */
    void removeActionReQueue(Intention i) {
        if (!i.isFinished()) {
            i.peek().removeCurrentStep();
            c.addRunningIntention(i);
        }
    }

    private static final Literal WAIT_GOAL_CONDITION = Literal.atom("wait_goal_condition");

    /** ClrInt: pops finished intended means, passing results back to the caller's step. */
    void applyClrInt(Intention i) {
        while (true) {
            if (i.isFinished()) {
                c.removeRunningIntention(i);
                return;
            }
            IntendedMeans im = i.peek();
            if (!im.isFinished()) {
                return;
            }
            if (i.hasGoalCondition()) {
                // Jason 3.2.0: once any plan of an intention holding a goal condition ends, the
                // intention waits in PI until a goal condition of it holds
                c.removeRunningIntention(i);
                c.addPendingIntention(String.valueOf(i.id()), WAIT_GOAL_CONDITION, i);
                return;
            }
            IntendedMeans topIM = i.pop();
            Trigger topTrigger = topIM.trigger();
            Term topLiteral = topTrigger.literal();
            if (topTrigger.isGoal() && ag.goalStates().listening()) {
                ag.goalStates().finished(GoalStates.of(topIM), GoalStates.State.achieved);
            }
            if (topTrigger.isGoal() && !topTrigger.isAddition() && !i.isFinished()) {
                // a failure plan finished: drop the intended means up to the goal that failed
                im = i.peek();
                // as Jason's, a caller that posted the goal through a variable (!G) ends here too
                if (im.isFinished() || !(im.currentStep().kind() == BodyStep.Kind.ACHIEVE
                        && im.unifier().copy().unifies(im.currentStep().term(), topLiteral))
                        || im.currentStep().term() instanceof Var || im.currentStep().term() instanceof AnnotatedVar) {
                    im = i.pop();
                }
                while (!i.isFinished()
                        && !(im.trigger().isGoal() && im.unifier().copy().unifies(im.trigger().literal(), topLiteral))
                        && !(!im.isFinished() && im.currentStep().kind() == BodyStep.Kind.ACHIEVE
                                && im.unifier().copy().unifies(im.currentStep().term(), topLiteral))) {
                    im = i.pop();
                }
            }
            if (!i.isFinished()) {
                im = i.peek();
                if (!im.isFinished()) {
                    joinRenamedVars(im, topIM.unifier());
                    im.removeCurrentStep();
                }
            }
        }
    }

    /** Binds the caller's variables renamed for an event to the values the callee gave them. */
    void joinRenamedVars(IntendedMeans im, Unifier values) {
        if (im.renamedVars() == null) {
            return;
        }
        for (Map.Entry<Var, Var> e : im.renamedVars().entrySet()) {
            Var vt = e.getValue();
            im.unifier().unifies(e.getKey(), vt);
            Term value = values.deref(vt);
            if (!(value instanceof Var)) {
                Term applied = values.apply(value);
                im.unifier().bind(vt, renameApart(applied));
            }
        }
    }

    /** Gives the free variables of a value fresh names (they came from another plan). */
    Term renameApart(Term t) {
        return Renamer.renameApart(t, ag);
    }

    // ---- failure ------------------------------------------------------------------------------

    static List<Term> errorAnnots(String id, String message) {
        var out = new ArrayList<Term>();
        out.add(Literal.of("error", Literal.atom(id)));
        out.add(Literal.of("error_msg", new StringTerm(message)));
        return out;
    }

    /** Generates {@code -!g} for the intention's top goal (or the nearest goal with a failure plan). */
    boolean generateGoalDeletion(Intention i, List<Term> annots) {
        IntendedMeans im = i.peek();
        Event failEvent = findEventForFailure(i, im.trigger());
        boolean relevant = failEvent != null;
        if (!relevant) {
            failEvent = new Event(im.trigger(), i);
        }
        BodyStep step = im.currentStep();
        failEvent = withFailureAnnots(failEvent, step == null ? null : step.withTerm(im.unifier().apply(step.term())), annots);
        if (failEvent.trigger().isGoal()) {
            notifyFailed(GoalStates.of(im), relevant, i, im, annots);
            if (relevant) {
                // the intention now waits for its failure event: an atomic one must leave I, or
                // SelInt would run its failed step again and SelEv never take the event (Jason's
                // removeAtomicIntention after a failed action; an action failing at once looped)
                if (i.isAtomic()) {
                    c.removeRunningIntention(i);
                }
                c.addEvent(failEvent);
            } else {
                ag.warn("No failure event was generated for " + failEvent.trigger() + "\n" + i.jasonText());
                var listener = ag.unhandledFailureListener();
                if (listener != null && failEvent.trigger().literal() instanceof Literal failed) {
                    IntendedMeans root = i.bottom();
                    listener.failureUnhandled(failed, root.trigger().literal() instanceof Literal r ? r : failed);
                }
                ag.dropIntention(i);
            }
        } else {
            ag.warn("Could not finish intention: " + failEvent.trigger());
            ag.dropIntention(i);
        }
        return relevant;
    }

    private boolean generateGoalDeletionFromEvent(Event se, List<Term> annots) {
        Trigger te = se.trigger();
        if (te.isAddition() && te.isGoal()) {
            Event failEvent = se.isExternal() ? externalFailureEvent(te) : findEventForFailure(se.intention(), te);
            notifyFailed(te, failEvent != null, se.intention(), null, annots);
            if (failEvent != null) {
                // the goal's code_src and code_line are those of the step that posted it, as Jason's
                Intention i = se.intention();
                BodyStep caller = i == null || i.peek() == null ? null : i.peek().currentStep();
                BodyStep goal = new BodyStep(BodyStep.Kind.ACHIEVE, te.literal(), caller == null ? null : caller.source());
                c.addEvent(withFailureAnnots(failEvent, goal, annots));
                return true;
            }
            // Jason's wording here differs from generateGoalDeletion's ("fail event"), and its dump of
            // the intention starts with an empty line; the caller then says why the goal failed
            ag.warn("No fail event was generated for " + te);
            if (se.intention() != null) {
                ag.warn("\n" + se.intention().jasonText());
                ag.dropIntention(se.intention());
            }
            return false;
        }
        if (!se.isExternal()) {
            // a failure event no plan applies to (the caller says so too, as Jason): a .fail_goal's own
            // intention goes on past the failed goal, as Jason's; one that waited for the event is dropped
            Intention i = se.intention();
            ag.warn("Could not finish intention:\n" + i.jasonText());
            if (i == heldForFailureEvent && !i.isFinished()) {
                heldForFailureEvent = null;
                c.addRunningIntention(i);
            } else if (!c.hasRunningIntention(i)) {
                ag.dropIntention(i);
            }
            return false;
        }
        // an external -!g with no plan (a waiting !!g that .fail_goal ended): the caller warns too
        ag.warn("Discarding external event: " + te);
        return false;
    }

    /** Goal states of a failure: failed, then handled by a failure plan or finished with the goals below. */
    private void notifyFailed(Trigger goal, boolean handled, Intention i, IntendedMeans failedIM, List<Term> annots) {
        GoalStates gs = ag.goalStates();
        Term reason = annots.isEmpty() ? null : annots.get(0);
        gs.post(goal, GoalStates.State.failed, reason);
        if (handled) {
            gs.post(goal, GoalStates.State.executing, Literal.atom("has_failure_plan"));
            return;
        }
        gs.finished(goal, null);
        if (i != null) {
            for (IntendedMeans other : i) {
                if (other != failedIM) {
                    gs.finished(GoalStates.of(other), GoalStates.State.failed);
                }
            }
        }
    }

    private Event externalFailureEvent(Trigger te) {
        Trigger fail = new Trigger(Trigger.Op.DEL, te.type(), te.literal());
        return ag.planLibrary().hasCandidate(fail) ? new Event(fail, null) : null;
    }

    /** Jason's search down the stack for a goal with a relevant failure plan. */
    Event findEventForFailure(Intention i, Trigger tevent) {
        Iterator<IntendedMeans> ii = i.iterator();
        if (tevent.isGoal() && !tevent.isAddition()) {
            // failure inside a failure plan: continue below the goal that failed
            IntendedMeans im = ii.next();
            boolean found = false;
            while (ii.hasNext() && !found) {
                im = ii.next();
                while (ii.hasNext() && im.unifier().copy().unifies(im.trigger().literal(), tevent.literal())) {
                    im = ii.next();
                    found = true;
                }
            }
            tevent = im.trigger();
        }
        Trigger failTrigger = new Trigger(Trigger.Op.DEL, tevent.type(), tevent.literal());
        while (!ag.planLibrary().hasCandidate(failTrigger) && ii.hasNext()) {
            tevent = ii.next().trigger();
            failTrigger = new Trigger(Trigger.Op.DEL, tevent.type(), tevent.literal());
        }
        if (tevent.isGoal() && ag.planLibrary().hasCandidate(failTrigger)) {
            return new Event(failTrigger, i);
        }
        return null;
    }

    private Term anonymous(Term t) {
        return Renamer.renameApart(t, x -> ag.freshVar(ANONYMOUS), new HashMap<>());
    }

    private static final Var ANONYMOUS = new Var("_");

    /** Adds error, error_msg, code, code_src and code_line annotations to a failure event. */
    private Event withFailureAnnots(Event e, BodyStep step, List<Term> annots) {
        // no step and nothing to say: no annotation, as Jason (a failed ask's answer at the plan's end)
        if (!(e.trigger().literal() instanceof Literal lit) || step == null && annots.isEmpty()) {
            return e;
        }
        var all = new ArrayList<Term>(annots);
        if (step != null && step.source() != null) {
            all.add(Literal.of("code_src", new StringTerm(step.source().jasonFile())));
            all.add(Literal.of("code_line", new NumberTerm(step.source().line())));
        }
        if (lit.getAnnot("code") == null && annots.stream().noneMatch(a -> a instanceof Literal l && l.functor().equals("code"))) {
            // the formula without its operator (?, +, !...), free variables made anonymous, as Jason
            Term code = step == null ? Literal.atom("no_code") : anonymous(step.term());
            all.add(Literal.of("code", code));
        }
        return new Event(e.trigger().withLiteral(lit.addAnnots(all)), e.intention());
    }
}
