package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Message;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/**
 * {@code .send(Receiver, Performative, Content[, Answer[, Timeout]])}: sends a message. An ask
 * with an answer argument suspends the intention until the reply (or the timeout, which binds
 * the answer to {@code timeout}). Any other performative's fourth argument is the id of the ask
 * the message answers (a {@code kqml_received} plan replying, as Jason's).
 */
final class Send extends DefaultInternalAction {
    Send() {
        super(".send", 3, 5);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String performative = text(args[1]);
        boolean syncAsk = args.length >= 4 && performative.startsWith("ask");
        int serial = ag.nextMessageSerial();
        // Jason numbers a synchronous ask a second time, under its own prefix (its replies are told apart by it)
        String syncId = syncAsk ? Message.SYNC_ASK_PREFIX + ag.nextMessageSerial() : null;
        String inReplyTo = args.length >= 4 && !syncAsk ? text(args[3]) : null;
        if (args[0] instanceof ListTerm l) {
            for (Term r : l.elements()) {
                send(ag, serial, syncId, text(r), performative, args[2], inReplyTo);
            }
        } else {
            send(ag, serial, syncId, text(args[0]), performative, args[2], inReplyTo);
        }
        if (syncAsk) {
            Intention si = ag.circumstance().selectedIntention();
            ag.circumstance().addPendingIntention(syncId, Message.waitingFor(syncId), si);
            ag.holdSelectedIntention();
            if (args.length == 5) {
                long due = ag.clock().millis() + (long) number(args[4]);
                Term answer = args[3];
                ag.schedule(due, () -> {
                    if (ag.circumstance().removePendingIntention(syncId) == si) {
                        // an ask to many ends with the answers come so far; an ask to one with timeout
                        si.peek().unifier().unifies(answer, args[0] instanceof ListTerm
                                ? Message.answersSoFar(si.peek().unifier(), syncId) : Literal.atom("timeout"));
                        si.peek().removeCurrentStep();
                        ag.circumstance().addRunningIntention(si);
                    }
                });
            }
        }
        return true;
    }

    private static void send(Agent ag, int serial, String syncId, String receiver, String performative, Term content,
            String inReplyTo) throws IaException {
        if (receiver.equals("self")) {
            receiver = ag.name(); // a message to oneself names its sender self (Jason's kqml_received)
        }
        Message m = syncId != null ? new Message(syncId, ag.name(), receiver, performative, content, inReplyTo)
                : Message.numbered(serial, ag.name(), receiver, performative, content, inReplyTo);
        if (!ag.arch().sendMessage(m)) {
            throw IaException.receiverNotFound(m);
        }
    }
}
