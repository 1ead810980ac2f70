package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;

/** {@code .concat(A, B, ..., R)}: concatenates lists, or strings (other terms as text). */
final class Concat extends DefaultInternalAction {
    Concat() {
        super(".concat", 2, 2147483647);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        int n = args.length - 1;
        boolean lists = true;
        for (int i = 0; i < n; i++) {
            lists &= args[i] instanceof ListTerm;
        }
        if (lists) {
            var all = new ArrayList<Term>();
            for (int i = 0; i < n; i++) {
                all.addAll(((ListTerm) args[i]).elements());
            }
            return un.unifies(args[n], listOf(all));
        }
        var sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            sb.append(text(args[i]));
        }
        return un.unifies(args[n], new StringTerm(sb.toString()));
    }
}
