package jacabot.agent.semantics;

import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Term;

/**
 * Internal actions the agent does not know, reported before it runs as Jason's parser reports
 * them (a warning per call written in a plan; the program runs on and Jason makes each call an
 * environment action, which {@link BodyExecutor} does too). Looked for at the first reasoning
 * cycle, once the architecture has added its libraries' actions.
 */
final class UnknownActions {
    private UnknownActions() {
    }

    static void report(Agent ag) {
        for (Plan p : ag.planLibrary().plans()) {
            if (!ag.planLibrary().isKqmlPlan(p)) {
                steps(ag, p.body());
            }
        }
    }

    private static void steps(Agent ag, BodyTerm body) {
        for (BodyStep s : body.steps()) {
            if (s.kind() == BodyStep.Kind.INTERNAL_ACTION && s.term() instanceof Literal l) {
                if (ag.internalAction(l.functor()) == null) {
                    String where = s.source() == null ? "" : "[" + s.source().jasonPosition() + "] ";
                    ag.arch().console("[aslparser] " + where + "warning: The internal action class for '" + l
                            + "' was not loaded! Error: java.lang.ClassNotFoundException: " + className(l.functor()));
                }
                for (Term arg : l.args()) {
                    if (arg instanceof BodyTerm b) {
                        steps(ag, b); // the blocks of if, while and for
                    }
                }
            }
        }
    }

    /** The class Jason looks for: {@code .foo} is {@code jason.stdlib.foo}, {@code lib.foo} is itself. */
    private static String className(String functor) {
        return functor.startsWith(".") ? "jason.stdlib." + functor.substring(1) : functor;
    }
}
