package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Trigger;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.function.Predicate;

/** A stack of intended means, the top being the plan that runs. */
public final class Intention implements Iterable<IntendedMeans> {
    private final int id;
    private final ArrayDeque<IntendedMeans> stack = new ArrayDeque<>();
    /** The top of the stack, or null: asked several times in every cycle. */
    private IntendedMeans top;
    private int atomicCount;
    /** How many intended means have a goal condition (Jason's imWithGoalCondition). */
    private int goalConditions;
    private boolean suspended;

    Intention(int id) {
        this.id = id;
    }

    /** {@return a copy of this intention's stack under another id (Jason's fork)} */
    Intention copyAs(int newId) {
        Intention c = new Intention(newId);
        var ims = new ArrayList<IntendedMeans>(stack);
        for (int k = ims.size() - 1; k >= 0; k--) {
            c.push(ims.get(k).copy());
        }
        c.suspended = suspended;
        return c;
    }

    public int id() {
        return id;
    }

    public void push(IntendedMeans im) {
        stack.push(im);
        top = im;
        if (im.isAtomic()) {
            atomicCount++;
        }
        if (im.hasGoalCondition()) {
            goalConditions++;
        }
    }

    public IntendedMeans pop() {
        IntendedMeans im = stack.pop();
        top = stack.peek();
        if (im.isAtomic()) {
            atomicCount--;
        }
        if (im.hasGoalCondition()) {
            goalConditions--;
        }
        return im;
    }

    public IntendedMeans peek() {
        return top;
    }

    /** {@return the intended means at the bottom of the stack (the goal the intention was started for), or null} */
    public IntendedMeans bottom() {
        return stack.peekLast();
    }

    public int size() {
        return stack.size();
    }

    public boolean isFinished() {
        return top == null;
    }

    public boolean isAtomic() {
        return atomicCount > 0;
    }

    /** {@return whether some intended means of the stack has a goal condition} */
    public boolean hasGoalCondition() {
        return goalConditions > 0;
    }

    public boolean isSuspended() {
        return suspended;
    }

    public void markSuspended(boolean suspended) {
        this.suspended = suspended;
    }

    /** {@return whether some intended means of this intention handles a goal unifying with g} */
    public boolean hasGoal(Literal g, Unifier u) {
        for (IntendedMeans im : stack) {
            Trigger t = im.trigger();
            if (t.isAchieveGoal() && t.isAddition() && u.copy().unifies(g, t.literal())) {
                return true;
            }
        }
        return false;
    }

    /** {@return whether some intended means handles {@code +!g}; binds {@code u} to the first match} */
    public boolean hasGoalBinding(Literal g, Unifier u) {
        for (IntendedMeans im : stack) {
            Trigger t = im.trigger();
            if (t.isAchieveGoal() && t.isAddition() && u.unifies(g, t.literal())) {
                return true;
            }
        }
        return false;
    }

    /**
     * Removes the intended means down to and including the topmost one for goal {@code g}, as
     * many times as the goal occurs. {@return the last removed intended means for g, or null}
     */
    public IntendedMeans dropGoal(Literal g, Unifier u) {
        return dropGoal(im -> im.trigger().isAchieveGoal() && im.trigger().isAddition()
                && u.copy().unifies(g, im.trigger().literal()));
    }

    /**
     * Removes the intended means down to and including the topmost one that passes the test, as
     * long as one does. {@return the last removed intended means that passed, or null}
     */
    public IntendedMeans dropGoal(Predicate<IntendedMeans> test) {
        IntendedMeans result = null;
        IntendedMeans target = find(test);
        while (target != null) {
            result = target;
            while (peek() != target) {
                pop();
            }
            pop();
            target = find(test);
        }
        return result;
    }

    private IntendedMeans find(Predicate<IntendedMeans> test) {
        for (IntendedMeans im : stack) {
            if (test.test(im)) {
                return im;
            }
        }
        return null;
    }

    /** Iterates from the top of the stack down. */
    @Override
    public Iterator<IntendedMeans> iterator() {
        return stack.iterator();
    }

    @Override
    public String toString() {
        var sb = new StringBuilder();
        for (IntendedMeans im : stack) {
            sb.append("    ").append(im).append('\n');
        }
        return sb.toString();
    }

    /**
     * {@return the intention as Jason's warnings print it: its number, then a line per intended
     * means, top first, with what is left of its body and its unifier}
     */
    public String jasonText() {
        var sb = new StringBuilder("intention ").append(id).append(": \n");
        int shown = 0;
        for (IntendedMeans im : stack) {
            String body = im.remainingBody();
            sb.append("    ").append(im.trigger()).append(" <- ").append(body.isEmpty() ? "." : "... " + body)
                    .append(" / ").append(JasonHashOrder.text(im.unifier())).append('\n');
            if (shown++ > 40) {
                sb.append("... more ").append(stack.size() - 40).append(" intended means!\n");
                break;
            }
        }
        return stack.isEmpty() ? sb.append("<finished intention>").toString() : sb.toString();
    }
}
