package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.List;

/**
 * An environment action sent to the architecture, with its result once the environment has
 * executed it. The architecture reports the outcome with {@link #succeed()} or {@link #fail}.
 */
public final class ActionExec {
    private final Literal action;
    private final Intention intention;
    private volatile boolean result;
    private volatile String failureMessage;
    private volatile List<Term> failureReason = List.of();
    private volatile Unifier outputs;

    ActionExec(Literal action, Intention intention) {
        this.action = action;
        this.intention = intention;
    }

    /** {@return the action, with its arguments bound} */
    public Literal action() {
        return action;
    }

    public Intention intention() {
        return intention;
    }

    public void succeed() {
        result = true;
    }

    /** Succeeds and binds variables of the action (e.g. an operation's output parameters). */
    public void succeed(Unifier bindings) {
        outputs = bindings;
        result = true;
    }

    /** Fails; {@code reason} terms are added to the failure event's annotations. */
    public void fail(String message, List<Term> reason) {
        result = false;
        failureMessage = message;
        failureReason = List.copyOf(reason);
    }

    public boolean result() {
        return result;
    }

    public String failureMessage() {
        return failureMessage;
    }

    public List<Term> failureReason() {
        return failureReason;
    }

    Unifier outputs() {
        return outputs;
    }

    @Override
    public String toString() {
        return action.toString();
    }
}
