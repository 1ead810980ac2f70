package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;

/**
 * A message between agents (KQML-like performatives: tell, untell, achieve, askOne, askAll, ...).
 *
 * @param inReplyTo the id of the ask this message answers, or null
 */
public record Message(String id, String sender, String receiver, String performative, Term content,
        String inReplyTo) {
    @Override
    public String toString() {
        return "<" + id + "," + sender + "," + performative + "," + receiver + "," + content
                + (inReplyTo == null ? "" : "," + inReplyTo) + ">";
    }
}
