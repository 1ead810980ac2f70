package jacabot.agent.semantics;

import jacabot.agent.syntax.BodyStep;
import java.util.List;

/** The remaining steps of an intended means: an immutable linked list, cheap to prepend to. */
public final class StepList {
    final BodyStep head;
    final StepList next;

    StepList(BodyStep head, StepList next) {
        this.head = head;
        this.next = next;
    }

    /** {@return the steps followed by {@code rest}} */
    static StepList of(List<BodyStep> steps, StepList rest) {
        StepList list = rest;
        for (int i = steps.size() - 1; i >= 0; i--) {
            list = new StepList(steps.get(i), list);
        }
        return list;
    }

    public BodyStep head() {
        return head;
    }

    public StepList next() {
        return next;
    }
}
