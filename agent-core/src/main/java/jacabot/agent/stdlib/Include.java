package jacabot.agent.stdlib;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.io.IOException;
import java.nio.file.Path;

/**
 * {@code .include(File[, NS])}: reads an AgentSpeak file into the running agent, as the
 * {@code include} directive does when the agent is loaded: its beliefs (with their events),
 * rules, plans and goals are added. With NS the file is a module read in that namespace (its
 * local namespaces get names of their own); an unbound NS is given a new namespace.
 */
final class Include extends DefaultInternalAction {
    Include() {
        super(".include", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String source = text(args[0]);
        Term ns = null;
        if (args.length > 1) {
            if (args[1] instanceof Var) {
                ns = ag.parser().freshNamespace();
            } else if (args[1] instanceof Literal a && a.isAtom()) {
                ns = a;
            } else {
                throw IaException.wrongArguments(name(), "the namespace must be an atom or a variable, not '" + args[1] + "'");
            }
        }
        Path file = ag.parser().locate(source);
        if (file == null) {
            throw IaException.wrongArguments(name(), "the file '" + source + "' was not found");
        }
        AgentProgram program;
        try {
            // one parser serves all the agents of a project, which may include at the same time
            synchronized (ag.parser()) {
                program = ag.parser().parseFile(file, ns);
            }
        } catch (AslSyntaxException | IOException e) {
            throw IaException.wrongArguments(name(), e.getMessage());
        }
        ag.load(program);
        return args.length > 1 && args[1] instanceof Var ? un.unifies(args[1], ns) : true;
    }
}
