package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;

/**
 * {@code .asserta(B)} and {@code .assertz(B)}: B added at the beginning (as {@code +B}) or the
 * end of its beliefs. As Jason's: only asserta adds {@code source(self)} (to a B without a
 * source; assertz adds B as written), a belief already there stays where it is, the {@code +B}
 * event has a new focus (the caller goes on), and a B with variables is stored as it is.
 */
final class AssertBelief extends DefaultInternalAction {
    private final boolean atEnd;

    private AssertBelief(String name, boolean atEnd) {
        super(name, 1, 1);
        this.atEnd = atEnd;
    }

    static AssertBelief asserta() {
        return new AssertBelief(".asserta", false);
    }

    static AssertBelief assertz() {
        return new AssertBelief(".assertz", true);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof Literal l) || l.functor().equals(Literal.RULE_TERM)) {
            // Jason fails with a class cast error, hence error(unknown)
            throw new IaException("unknown", "Wrong argument for internal action '" + name().substring(1) + "': '" + args[0] + "' is not a literal");
        }
        Literal added = ag.addBelief(atEnd || l.hasSource() ? l : l.addAnnot(Literal.SOURCE_SELF), atEnd);
        if (added != null) {
            ag.circumstance().addBeliefEvent(Trigger.Op.ADD, added);
        }
        return true;
    }
}
