package jacabot.agent.stdlib;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.io.IOException;
import java.nio.file.Path;

/**
 * {@code .create_agent(Name, Source[, Options])}: a new agent running the program in Source
 * (looked up in the creator's source path). Options are accepted and not used.
 */
final class CreateAgent extends DefaultInternalAction {
    CreateAgent() {
        super(".create_agent", 2, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        boolean unbound = args[0] instanceof Var || args[0] instanceof AnnotatedVar;
        String name = text(args[0]);
        if (unbound && !name.isEmpty()) { // as Jason: a variable's own name, its first letter in lower case
            name = name.substring(0, 1).toLowerCase(java.util.Locale.ROOT) + name.substring(1);
        }
        String source = text(args[1]);
        Path file = ag.parser().locate(source);
        if (file == null) {
            throw IaException.wrongArguments(name(), "the source '" + source + "' was not found");
        }
        AgentProgram program;
        try {
            program = ag.parser().parseFile(file);
        } catch (AslSyntaxException | IOException e) {
            throw IaException.wrongArguments(name(), e.getMessage());
        }
        String created;
        try {
            created = ag.arch().createAgent(name, program, ag.parser());
        } catch (IllegalArgumentException e) {
            throw IaException.wrongArguments(name(), e.getMessage());
        }
        if (created == null) {
            throw IaException.wrongArguments(name(), "this infrastructure cannot create agents");
        }
        // as Jason: a name taken is the next free one (NAME_1, ...), which only a variable is bound to, as a string
        return !unbound || un.unifies(args[0], new StringTerm(created));
    }
}
