package jacabot.agent.stdlib;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.CircumstanceListener;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.GoalStates;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.TriggerTerm;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * {@code .wait(ms)}, {@code .wait({+e})}, {@code .wait("+e")}, {@code .wait(Formula)}, each with an
 * optional timeout in ms and elapsed-time output: {@code .wait(E, T, Elapsed)}. Without an
 * elapsed-time argument a timeout fails the intention with {@code error(wait_timeout)}. Times are
 * read from the agent's clock, so they are simulated when a simulator drives the clock.
 */
final class Wait extends DefaultInternalAction {
    /**
     * Event strings parse once: an agent waits for the same event again and again
     * ({@code .wait("+cylinderDetected", 8000)}), and parsing dwarfs the rest of the action.
     * Triggers are immutable, so every agent can share them.
     */
    private static final Map<String, Optional<Trigger>> PARSED = new ConcurrentHashMap<>();
    private static final int PARSED_MAX = 1024;

    Wait() {
        super(".wait", 1, 3);
    }

    @Override
    public boolean suspendsIntention() {
        return true;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        long timeout = -1;
        Trigger te = null;
        Term formula = null;
        Term elapsed = null;
        Intention si = ag.circumstance().selectedIntention();
        if (args[0] instanceof NumberTerm n) {
            timeout = (long) n.value();
        } else {
            te = trigger(ag, args[0]);
            if (te == null) {
                if (!(args[0] instanceof Literal || args[0] instanceof LogExpr || args[0] instanceof RelExpr)) {
                    throw IaException.wrongArguments(name(), "'" + args[0] + "' is neither a time, an event nor a formula");
                }
                formula = args[0];
                if (ag.solver().believes(formula, un)) {
                    si.peek().removeCurrentStep();
                    ag.circumstance().addRunningIntention(si);
                    return true;
                }
            }
            if (args.length >= 2) {
                timeout = (long) number(args[1]);
            }
            if (args.length == 3) {
                elapsed = args[2];
            }
        }
        new Waiting(ag, si, un, te, formula, timeout, elapsed).start();
        return true;
    }

    private static Trigger trigger(Agent ag, Term t) {
        if (t instanceof TriggerTerm tt) {
            return tt.trigger();
        }
        if (t instanceof StringTerm s) {
            if (PARSED.size() >= PARSED_MAX) {
                PARSED.clear(); // a program that builds its event strings: keep the memory bounded
            }
            return PARSED.computeIfAbsent(s.value(), text -> parse(ag, text)).orElse(null);
        }
        return null;
    }

    private static Optional<Trigger> parse(Agent ag, String text) {
        try {
            Term parsed = ag.parser().parseTerm("{" + text + "}");
            return parsed instanceof TriggerTerm tt ? Optional.of(tt.trigger()) : Optional.empty();
        } catch (AslSyntaxException e) {
            return Optional.empty();
        }
    }

    /** A suspended intention waiting for an event, a formula or a time. */
    private static final class Waiting implements CircumstanceListener {
        private final Agent ag;
        private final Intention si;
        private final Unifier un;
        private final Trigger te;
        private final Term formula;
        private final long timeout;
        private final Term elapsedTerm;
        private final String key;
        private final long start;
        private boolean done;
        private boolean dropped;

        Waiting(Agent ag, Intention si, Unifier un, Trigger te, Term formula, long timeout, Term elapsedTerm) {
            this.ag = ag;
            this.si = si;
            this.un = un;
            this.te = te;
            this.formula = formula;
            this.timeout = timeout;
            this.elapsedTerm = elapsedTerm;
            this.start = ag.clock().millis();
            Term what = te != null ? te.literal() : formula != null ? formula : Literal.of("time", new NumberTerm(timeout));
            Literal reason = Literal.of("wait", new NumberTerm(si.id())).addAnnot(what);
            this.key = reason.toString();
            ag.circumstance().addPendingIntention(key, reason, si);
            ag.goalStates().ofTop(si, GoalStates.State.waiting, reason);
        }

        void start() {
            ag.circumstance().addListener(this);
            if (timeout >= 0) {
                ag.schedule(start + timeout, () -> resume(true));
            }
        }

        @Override
        public void eventAdded(Event e) {
            if (!dropped) {
                test(e);
            }
        }

        /**
         * A wait for a time hears no belief event, and a wait for an event only those that may
         * match it (its type, operator, functor and arity); a wait for a formula tests it at every
         * event, so it hears them all.
         */
        @Override
        public boolean hearsBeliefEvent(Trigger.Op op, Literal b) {
            if (done || dropped) {
                return false;
            }
            if (formula != null) {
                return true;
            }
            return te != null && te.type() == Trigger.Type.BELIEF && te.op() == op
                    && (!(te.literal() instanceof Literal l) || l.functor().equals(b.functor()) && l.arity() == b.arity());
        }

        @Override
        public void intentionAdded(Intention i) {
            test(null);
        }

        @Override
        public void intentionDropped(Intention i) {
            if (i == si) {
                dropped = true;
                resume(false);
            } else {
                test(null);
            }
        }

        private void test(Event e) {
            if (done) {
                return;
            }
            if (e != null && te != null && te.op() == e.trigger().op() && te.type() == e.trigger().type()
                    && un.unifies(te.literal(), e.trigger().literal())) {
                resume(false);
            } else if (formula != null && ag.solver().believes(formula, un)) {
                resume(false);
            }
        }

        private void resume(boolean byTimeout) {
            if (done) {
                return;
            }
            done = true;
            ag.circumstance().removeListener(this);
            ag.runAtBeginOfNextCycle(() -> {
                if (ag.circumstance().removePendingIntention(key) != si || dropped
                        || !si.isAtomic() && ag.circumstance().hasRunningIntention(si)) {
                    return;
                }
                if (byTimeout && (te != null || formula != null) && elapsedTerm == null) {
                    ag.failIntention(si, "wait_timeout", "timeout in .wait");
                } else if (!si.isFinished()) {
                    si.peek().removeCurrentStep();
                    if (elapsedTerm != null) {
                        un.unifies(elapsedTerm, new NumberTerm(ag.clock().millis() - start));
                    }
                    if (si.isSuspended()) {
                        ag.circumstance().addPendingIntention(Suspensions.SUSPENDED + si.id(), Suspensions.REASON, si);
                    } else {
                        ag.circumstance().addRunningIntention(si);
                        ag.goalStates().ofTop(si, GoalStates.State.executing, null);
                    }
                }
            });
        }
    }
}
