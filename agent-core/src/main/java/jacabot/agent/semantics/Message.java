package jacabot.agent.semantics;

import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.Objects;

/**
 * A message between agents (KQML-like performatives: tell, untell, achieve, askOne, askAll, ...).
 * A message an agent numbers ({@link #numbered}) makes its id, {@code mid}N, only when asked: a
 * stream of tells is never asked for it, and making the text was a tenth of sending.
 */
public final class Message {
    private volatile String id;
    private final int serial;
    private final String sender;
    private final String receiver;
    private final String performative;
    private final Term content;
    private final String inReplyTo;

    /** @param inReplyTo the id of the ask this message answers, or null */
    public Message(String id, String sender, String receiver, String performative, Term content, String inReplyTo) {
        this(Objects.requireNonNull(id), 0, sender, receiver, performative, content, inReplyTo);
    }

    private Message(String id, int serial, String sender, String receiver, String performative, Term content,
            String inReplyTo) {
        this.id = id;
        this.serial = serial;
        this.sender = sender;
        this.receiver = receiver;
        this.performative = performative;
        this.content = content;
        this.inReplyTo = inReplyTo;
    }

    /** {@return a message whose id is the sender's {@code mid}N, for N its serial ({@link Agent#nextMessageSerial})} */
    public static Message numbered(int serial, String sender, String receiver, String performative, Term content,
            String inReplyTo) {
        return new Message(null, serial, sender, receiver, performative, content, inReplyTo);
    }

    /** The prefix of a synchronous ask's id (Jason's {@code samid}N): a late answer to one is dropped. */
    public static final String SYNC_ASK_PREFIX = "samid";

    /** {@return the answers an ask to many has gathered so far in the asker's unifier (empty before the first)} */
    public static ListTerm answersSoFar(Unifier u, String askId) {
        return u.get(answersVar(askId)) instanceof ListTerm l ? l : ListTerm.EMPTY;
    }

    /** Keeps the answers an ask to many has gathered, under Jason's variable name. */
    static void keepAnswers(Unifier u, String askId, ListTerm answers) {
        u.bind(answersVar(askId), answers);
    }

    private static Var answersVar(String askId) {
        return new Var("AnsList___" + askId);
    }

    /** {@return why an intention waits for the answer to an ask: the pending reason {@code ask(Id)}} */
    public static Literal waitingFor(String askId) {
        return Literal.of("ask", Literal.atom(askId));
    }

    /** {@return the id of a message with this serial} */
    public static String idOf(int serial) {
        return "mid" + serial;
    }

    public String id() {
        String i = id;
        if (i == null) {
            i = idOf(serial);
            id = i;
        }
        return i;
    }

    public String sender() {
        return sender;
    }

    public String receiver() {
        return receiver;
    }

    public String performative() {
        return performative;
    }

    public Term content() {
        return content;
    }

    public String inReplyTo() {
        return inReplyTo;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Message m && id().equals(m.id()) && sender.equals(m.sender) && receiver.equals(m.receiver)
                && performative.equals(m.performative) && Objects.equals(content, m.content)
                && Objects.equals(inReplyTo, m.inReplyTo);
    }

    @Override
    public int hashCode() {
        return Objects.hash(id(), sender, receiver, performative, content, inReplyTo);
    }

    @Override
    public String toString() {
        // Jason's form, which its error messages quote: <id->inReplyTo,sender,performative,receiver,content>
        return "<" + id() + (inReplyTo == null ? "" : "->" + inReplyTo) + "," + sender + "," + performative + ","
                + receiver + "," + content + ">";
    }
}
