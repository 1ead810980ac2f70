package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.Locale;

/**
 * The directory facilitator's actions, as Jason's: {@code .df_register(S)},
 * {@code .df_deregister(S)}, {@code .df_subscribe(S)} and {@code .df_search(S, Agents)} (an
 * optional type argument before the last is accepted and, as in Jason's local DF, ignored).
 */
final class DfAction extends DefaultInternalAction {
    enum Kind { REGISTER, DEREGISTER, SUBSCRIBE, SEARCH }

    private final Kind kind;

    DfAction(Kind kind) {
        super(".df_" + kind.name().toLowerCase(Locale.ROOT), kind == Kind.SEARCH ? 2 : 1, kind == Kind.SEARCH ? 3 : 2);
        this.kind = kind;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String service = text(args[0]);
        boolean known;
        switch (kind) {
            case REGISTER:
                known = ag.arch().dfRegister(ag.name(), service);
                break;
            case DEREGISTER:
                known = ag.arch().dfDeregister(ag.name(), service);
                break;
            case SUBSCRIBE:
                known = ag.arch().dfSubscribe(ag.name(), service);
                break;
            default:
                var providers = ag.arch().dfSearch(service);
                if (providers == null) {
                    throw IaException.wrongArguments(name(), "this infrastructure has no directory facilitator");
                }
                var names = new ArrayList<Term>();
                providers.forEach(p -> names.add(Literal.atom(p)));
                return un.unifies(args[args.length - 1], listOf(names));
        }
        if (!known) {
            throw IaException.wrongArguments(name(), "this infrastructure has no directory facilitator");
        }
        return true;
    }
}
