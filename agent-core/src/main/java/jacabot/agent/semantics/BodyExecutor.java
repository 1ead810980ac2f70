package jacabot.agent.semantics;

import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.Var;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;

/** ExecInt: runs the current step of the selected intention, one handler per kind of formula. */
final class BodyExecutor {
    private static final Var ANY = new Var("_");
    private final Agent ag;
    private final ReasoningCycle rc;
    private final Circumstance c;

    BodyExecutor(Agent ag, ReasoningCycle rc) {
        this.ag = ag;
        this.rc = rc;
        this.c = ag.circumstance();
    }

    void execute(Intention i) {
        if (i.isFinished()) {
            return;
        }
        IntendedMeans im = i.peek();
        if (im.isFinished()) {
            rc.removeActionReQueue(i);
            return;
        }
        BodyStep step = im.currentStep();
        Term term = step.term();
        BodyStep.Kind kind = step.kind();
        if (term instanceof Var || term instanceof AnnotatedVar && kind == BodyStep.Kind.ACTION) {
            term = im.unifier().apply(term);
            if (term instanceof Var || term instanceof AnnotatedVar) {
                rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("body_var_without_value",
                        step.source() + ": Variable '" + step.term() + "' must be ground."));
                return;
            }
            if (term instanceof BodyTerm b && kind == BodyStep.Kind.ACTION) {
                im.replaceCurrentStep(step.withTerm(Literal.TRUE));
                im.insertAfterCurrent(b.steps());
                rc.removeActionReQueue(i);
                return;
            }
            if (term instanceof Literal l && l.isInternalAction() && kind == BodyStep.Kind.ACTION) {
                kind = BodyStep.Kind.INTERNAL_ACTION;
            }
        }
        try {
            run(i, im, step, kind, term);
        } catch (IllegalStateException e) {
            rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("body_var_not_literal", e.getMessage()));
        }
    }

    private void run(Intention i, IntendedMeans im, BodyStep step, BodyStep.Kind kind, Term term) {
        switch (kind) {
            case ACTION:
                action(i, im, term);
                break;
            case INTERNAL_ACTION:
                internalAction(i, im, step, (Literal) term);
                break;
            case CONSTRAINT:
                constraint(i, im, step, term);
                break;
            case ACHIEVE:
                c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, withDeadline(prepareForEvent(term, im, im))), i));
                break;
            case ACHIEVE_NEW_FOCUS:
                c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, withDeadline(prepareForEvent(term, im, null))), null));
                rc.removeActionReQueue(i);
                break;
            case TEST:
                test(i, im, term);
                break;
            case DEL_ADD_BEL:
                delAddBel(i, im, term);
                break;
            case ADD_BEL:
            case ADD_BEL_END:
            case ADD_BEL_NEW_FOCUS:
                addBel(i, im, kind, term);
                break;
            default:
                delBel(i, im, kind, term);
                break;
        }
    }

    private void action(Intention i, IntendedMeans im, Term term) {
        Term applied = im.unifier().apply(term);
        if (applied instanceof ArithFunction f) {
            // a function that could not be evaluated goes to the environment as the structure it
            // is written as (Jason's); one that evaluates gives a number, which is no action
            applied = Literal.of(f.name(), f.args());
        } else if (applied instanceof LogExpr e) {
            applied = e.op() == LogExpr.Op.NOT ? Literal.of("not", e.left())
                    : Literal.of(e.op() == LogExpr.Op.AND ? "&" : "|", e.left(), e.right());
        }
        if (!(applied instanceof Literal l)) {
            rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("body_var_not_literal",
                    "'" + applied + "' is not an action"));
            return;
        }
        c.setAction(new ActionExec(l, i));
    }

    private void internalAction(Intention i, IntendedMeans im, BodyStep step, Literal body) {
        InternalAction ia = ag.internalAction(body.functor());
        if (ia == null) {
            // as Jason, which reported it at load: an action for the environment
            action(i, im, body);
            return;
        }
        boolean ok;
        try {
            Term[] args = ag.prepareArguments(ia, body, im.unifier());
            Object result = ia.execute(ag, im.unifier(), args);
            ok = false;
            if (result instanceof Boolean b) {
                ok = b;
            } else if (result instanceof Iterator<?> it && it.hasNext()) {
                im.setUnifier((Unifier) it.next());
                ok = true;
            }
            if (ok) {
                if (!ia.suspendsIntention() && !rc.isSelectedHeld() && !ag.isStopped()) {
                    rc.removeActionReQueue(i);
                }
                return;
            }
            rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("ia_failed", ""));
        } catch (IaException e) {
            if (!rc.generateGoalDeletion(i, e.failureAnnots())) {
                ag.warn("Error in internal action '" + step.term() + "' (" + step.source().jasonPosition() + "): "
                        + e.getMessage());
            }
        } catch (RuntimeException e) {
            String msg = "error in internal action " + body.functor() + ": " + e;
            if (!rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("ia_failed", msg))) {
                ag.warn(msg);
            }
        }
    }

    private void constraint(Intention i, IntendedMeans im, BodyStep step, Term term) {
        // the first solution is made in the intention's own unifier, as an internal action's
        if (ag.solver().believes(term, im.unifier())) {
            rc.removeActionReQueue(i);
        } else {
            // Jason's wording: the body from this formula on, the position and the unifier
            rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("constraint_failed", "Constraint " + im.remainingBody()
                    + " was not satisfied (" + step.source().jasonPosition() + ") un=" + im.unifier()));
        }
    }

    private void test(Intention i, IntendedMeans im, Term term) {
        if (ag.solver().believes(term, im.unifier())) {
            rc.removeActionReQueue(i);
            return;
        }
        if (term instanceof Literal || term instanceof Var || term instanceof AnnotatedVar) {
            Term applied = im.unifier().apply(term);
            if (applied instanceof Literal) {
                Literal body = prepareForEvent(term, im, im);
                Trigger te = new Trigger(Trigger.Op.ADD, Trigger.Type.TEST, body);
                if (ag.planLibrary().hasCandidate(te)) {
                    c.addEvent(new Event(te, i));
                    return;
                }
            }
        }
        rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("test_goal_failed", "Failed to test '" + term + "'"));
    }

    private void addBel(Intention i, IntendedMeans im, BodyStep.Kind kind, Term term) {
        boolean sameFocus = kind != BodyStep.Kind.ADD_BEL_NEW_FOCUS;
        // only a rule term, or a variable that may stand for one, needs applying here (+b(X) is applied below)
        Term bound = term instanceof Literal t && !t.functor().equals(Literal.RULE_TERM) ? term : im.unifier().apply(term);
        if (bound instanceof Literal r && r.functor().equals(Literal.RULE_TERM) && r.arity() == 2 && r.args().get(0) instanceof Literal head) {
            // +{ head :- body } adds a rule (renamed apart: its variables are its own)
            // (+R[source(A)] with R a rule: the annotations go to its head, source(self) when it has none)
            var rule = (Literal) Renamer.renameApart(r, ag);
            Literal ruleHead = ((Literal) rule.args().get(0)).addAnnots(rule.annots());
            ag.beliefBase().addRule(new Rule(ruleHead.hasSource() ? ruleHead : ruleHead.addAnnot(Literal.SOURCE_SELF),
                    rule.args().get(1)), kind == BodyStep.Kind.ADD_BEL_END);
            rc.removeActionReQueue(i);
            return;
        }
        Literal body = prepareForEvent(term, im, sameFocus ? im : null);
        Literal added = ag.addBelief(body, kind == BodyStep.Kind.ADD_BEL_END);
        if (added != null) {
            c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, added), sameFocus ? i : null));
            if (!sameFocus) {
                rc.removeActionReQueue(i);
            }
        } else {
            rc.removeActionReQueue(i);
        }
    }

    private void delBel(Intention i, IntendedMeans im, BodyStep.Kind kind, Term term) {
        boolean sameFocus = kind != BodyStep.Kind.DEL_BEL_NEW_FOCUS;
        Literal body = prepareForEvent(term, im, sameFocus ? im : null);
        // the usual -b(1) is found by its arguments, without a unifier to try candidates with
        Literal removed = preparedGround ? ag.beliefBase().removeFact(body) : null;
        // a plain -b(X, Y) with X and Y bound removed a fact with those arguments: unifying binds nothing
        boolean unified = removed != null && preparedPlain;
        if (removed == null) {
            removed = ag.removeBelief(body, ag.newUnifier());
        }
        if (removed != null) {
            // as Jason: -b(X) binds X to the belief removed (CArtAgO's producers count with it)
            if (!unified) {
                // (as Jason's, -b[x|T] leaves T free: the literal is unified without its tail)
                im.unifier().unifies(term instanceof Literal tl && tl.tail() != null
                        ? new Literal(tl.functor(), tl.args(), tl.annots(), tl.negated(), false, tl.ns()) : term, removed);
            }
            c.addEvent(new Event(new Trigger(Trigger.Op.DEL, Trigger.Type.BELIEF, removed), sameFocus ? i : null));
            if (!sameFocus) {
                rc.removeActionReQueue(i);
            }
        } else {
            rc.removeActionReQueue(i);
        }
    }

    /** {@code -+b}: removes the first belief like b (any arguments), then adds b. */
    private void delAddBel(Intention i, IntendedMeans im, Term term) {
        Literal body = prepareForEvent(term, im, im);
        Literal removed = removeAnyArgs(body);
        if (removed == NOT_GROUND) {
            Term[] anyArgs = new Term[body.arity()];
            for (int k = 0; k < anyArgs.length; k++) {
                anyArgs[k] = ag.freshVar(ANY);
            }
            Literal pattern = body.withArgs(List.of(anyArgs));
            removed = ag.removeBelief(pattern, ag.newUnifier());
        }
        if (removed != null) {
            c.addBeliefEvent(Trigger.Op.DEL, removed);
        }
        Literal added = ag.addBelief(body, false);
        if (added != null) {
            c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, added), i));
        } else {
            rc.removeActionReQueue(i);
        }
    }

    /** What {@link #removeAnyArgs} answers when it cannot tell. */
    private static final Literal NOT_GROUND = Literal.atom("not ground");
    /** Tries annotations (ground against ground: it binds nothing and stays empty). */
    private final Unifier groundAnnots = new Unifier();

    /**
     * As removing the first belief like {@code body} with each argument a fresh variable (what
     * {@code -+b} removes), among ground facts and with {@code body}'s annotations ground: the
     * facts are tried by their annotations alone, as the fresh variables take any arguments, and
     * the pattern is not built. {@return the removed part, null when no belief is like it, or
     * {@link #NOT_GROUND} when a fact or an annotation has variables (nothing was done)}
     */
    private Literal removeAnyArgs(Literal body) {
        if (body.arity() == 0 || body.ns() != null || body.tail() != null || !allGround(body.annots())) {
            return NOT_GROUND;
        }
        for (BeliefBase.Entry e : ag.beliefBase().current(body)) {
            if (e.rule() != null) {
                continue;
            }
            if (!e.isGround()) {
                return NOT_GROUND;
            }
            if (groundAnnots.unifiesAnnots(body.annots(), e.literal().annots())) {
                // the pattern's fresh variables would have taken numbers of the agent's counter
                ag.skipFreshVars(body.arity());
                return ag.beliefBase().remove(e.literal(), e.literal().withAnnots(body.annots()));
            }
        }
        ag.skipFreshVars(body.arity());
        return null;
    }

    /**
     * Jason's {@code !g[hard_deadline(T)]}: g fails with {@code error(deadline_reached)} when it is
     * still pursued T ms (on the agent's clock) after it was posted.
     */
    private Literal withDeadline(Literal goal) {
        if (goal.annots().size() < 2) {
            return goal; // a goal made ready for its event has a source: nothing else to look at
        }
        Literal d = goal.getAnnot("hard_deadline");
        if (d != null && d.arity() == 1 && d.args().get(0) instanceof NumberTerm n) {
            long ms = (long) n.value();
            ag.schedule(ag.clock().millis() + ms, () -> new GoalDropper(ag, GoalDropper.Mode.FAIL, goal, "deadline_reached",
                    "hard deadline of " + ms + " ms reached").drop());
        }
        return goal;
    }

    /** Whether the last literal {@link #prepareForEvent} made is ground. */
    private boolean preparedGround;
    /** Whether it came from a literal with neither annotations nor namespace, its variables all bound. */
    private boolean preparedPlain;

    /**
     * Applies the unifier, renames the free variables apart (remembering the renaming in
     * {@code caller} so that results come back) and adds {@code source(self)} when no source is
     * given.
     */
    Literal prepareForEvent(Term term, IntendedMeans im, IntendedMeans caller) {
        if (term instanceof Literal l && l.annots().isEmpty() && l.ns() == null && l.tail() == null) {
            // the usual +b(X) or !g(N + 1): one literal made, with its values and source(self)
            List<Term> args = im.unifier().applyAll(l.args());
            if (allGround(args)) {
                if (caller != null) {
                    caller.clearRenamedVars();
                }
                preparedGround = true;
                preparedPlain = true;
                return l.withArgsFromSelf(args);
            }
        }
        preparedPlain = false;
        Term applied = im.unifier().apply(term);
        if (!(applied instanceof Literal)) {
            throw new IllegalStateException("not a literal: " + applied);
        }
        Literal body = (Literal) applied;
        preparedGround = applied.isGround();
        if (preparedGround) {
            if (caller != null) {
                caller.clearRenamedVars();
            }
        } else {
            var renamed = new LinkedHashMap<Var, Var>();
            body = (Literal) Renamer.renameApart(applied, ag::freshVar, renamed);
            if (caller != null) {
                caller.setRenamedVars(renamed);
            }
        }
        return body.hasSource() ? body : body.addAnnot(Literal.SOURCE_SELF);
    }

    private static boolean allGround(List<Term> terms) {
        for (int k = 0, n = terms.size(); k < n; k++) {
            if (!terms.get(k).isGround()) {
                return false;
            }
        }
        return true;
    }

    static List<Term> elementsOf(Term t) {
        return t instanceof ListTerm l ? l.elements() : List.of();
    }
}
