package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;

/**
 * An internal action could not run (wrong arguments, unbound variable, ...). It fails the
 * intention with {@code error(errorId)} and {@code error_msg(message)}, as Jason does.
 */
public class IaException extends Exception {
    private static final long serialVersionUID = 1L;
    private final String errorId;
    private final transient List<Term> annots;

    public IaException(String errorId, String message) {
        this(errorId, message, List.of());
    }

    /** A failure with the given annotations for the {@code -!g} event (as {@code .fail(a1, ...)}). */
    public IaException(String errorId, String message, List<Term> annots) {
        super(message);
        this.errorId = errorId;
        this.annots = List.copyOf(annots);
    }

    public String errorId() {
        return errorId;
    }

    /** {@return the failure annotations: error and error_msg unless the action gave its own} */
    public List<Term> failureAnnots() {
        if (!annots.isEmpty()) {
            return new ArrayList<>(annots);
        }
        return ReasoningCycle.errorAnnots(errorId, getMessage() == null ? "" : getMessage());
    }

    /**
     * A message whose receiver does not exist: Jason's {@code receiver_not_found}, which also names
     * the agent ({@code agent_not_found(Name)}) among the failure's annotations.
     */
    public static IaException receiverNotFound(Message m) {
        String message = "Receiver '" + m.receiver() + "' does not exist! Could not send " + m;
        List<Term> annots = ReasoningCycle.errorAnnots("receiver_not_found", message);
        annots.add(Literal.of("agent_not_found", Literal.atom(m.receiver())));
        return new IaException("receiver_not_found", message, annots);
    }

    /** A wrong argument, in Jason's words (which name the action's class: {@code .map.put} is 'put'). */
    public static IaException wrongArguments(String ia, String why) {
        return new IaException("wrong_arguments", "Wrong argument for internal action '" + className(ia) + "': " + why);
    }

    /** A wrong number of arguments, in Jason's words. */
    public static IaException wrongArgumentCount(String ia, int min, int max) {
        String expected = min != max ? " From " + min + " to " + max + " arguments are expected."
                : min == 1 ? " One argument is expected." : " " + min + " arguments are expected.";
        return new IaException("wrong_arguments", "The internal action '" + className(ia)
                + "' has not received the required number of argument(s)." + expected);
    }

    private static String className(String ia) {
        return ia.substring(ia.lastIndexOf('.') + 1);
    }
}
