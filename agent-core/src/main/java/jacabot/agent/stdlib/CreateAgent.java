package jacabot.agent.stdlib;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
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
        String name = text(args[0]);
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
        return un.unifies(args[0], Literal.atom(created));
    }
}
