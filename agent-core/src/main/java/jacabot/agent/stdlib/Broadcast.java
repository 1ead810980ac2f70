package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Message;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .broadcast(Performative, Content)}: sends to every other agent. */
final class Broadcast extends DefaultInternalAction {
    Broadcast() {
        super(".broadcast", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String id = ag.nextMessageId();
        for (String name : ag.arch().agentNames()) {
            if (!name.equals(ag.name())) {
                ag.arch().sendMessage(new Message(id, ag.name(), name, text(args[0]), args[1], null));
            }
        }
        return true;
    }
}
