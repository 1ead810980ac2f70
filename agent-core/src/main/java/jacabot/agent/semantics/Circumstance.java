package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.BiPredicate;
import java.util.function.Predicate;

/**
 * The agent's circumstance, with Jason's formal components: events {@code E}, running intentions
 * {@code I}, pending intentions {@code PI}, pending actions {@code PA}, action feedback
 * {@code FA}, mailbox {@code MB}, and the selected event and intention {@code SE}, {@code SI}.
 */
public final class Circumstance {
    /** A suspended intention and why it waits. */
    public record Pending(Intention intention, Term reason) {
    }

    private final ArrayDeque<Event> events = new ArrayDeque<>();
    private Event atomicEvent;
    private final ArrayDeque<Intention> running = new ArrayDeque<>();
    private Intention atomicIntention;
    private boolean atomicIntentionSuspended;
    private final LinkedHashMap<String, Pending> pending = new LinkedHashMap<>();
    /** Events suspended before any plan was chosen for them (Jason's PE). */
    private final LinkedHashMap<String, Event> pendingEvents = new LinkedHashMap<>();
    private final HashMap<Integer, ActionExec> pendingActions = new HashMap<>();
    private final ConcurrentLinkedQueue<ActionExec> feedback = new ConcurrentLinkedQueue<>();
    /**
     * Guarded by itself: a lock taken without contention costs less than a lock-free queue's
     * compare-and-set chain while the code still runs interpreted, and adds no node per message.
     */
    private final ArrayDeque<Message> mailbox = new ArrayDeque<>();
    /** Written under the mailbox's lock, read without it (the agent's look for work). */
    private volatile int mailboxSize;
    /**
     * Replaced, not changed, when a listener comes or goes: a listener may remove itself while
     * notified, and tools attach from their own threads.
     */
    private volatile CircumstanceListener[] listeners = new CircumstanceListener[0];
    private GoalStates goalStates;
    private Predicate<Trigger> relevant;

    private Event selectedEvent;
    private Intention selectedIntention;
    /** The action the selected intention produced this cycle (Jason's C.A), or null. */
    private ActionExec action;

    // ---- events (E) -----------------------------------------------------------------------------

    /**
     * The agent's own: its goal states hear of every event (not a listener in Jason's sense), and
     * its plan library tells whether a plan is relevant for an event.
     */
    void own(GoalStates goalStates, Predicate<Trigger> relevant,
            BiPredicate<Trigger.Op, Literal> relevantBelief) {
        this.goalStates = goalStates;
        this.relevant = relevant;
        this.relevantBelief = relevantBelief;
    }

    /** {@link #relevant} for a belief event's parts. */
    private BiPredicate<Trigger.Op, Literal> relevantBelief;

    /**
     * Adds the external event {@code +b} or {@code -b} (op and b), as {@link #addEvent}; the event
     * and its trigger are made only when the event is kept (a told receiver's beliefs that no plan
     * is for are not).
     */
    public void addBeliefEvent(Trigger.Op op, Literal b) {
        if (relevantBelief != null && !relevantBelief.test(op, b) && unheard(op, b)) {
            return;
        }
        keep(new Event(new Trigger(op, Trigger.Type.BELIEF, b), null));
    }

    /** {@return whether no listener hears the belief event {@code op b} (see {@link CircumstanceListener#hearsBeliefEvent})} */
    private boolean unheard(Trigger.Op op, Term b) {
        for (CircumstanceListener l : listeners) {
            if (!(b instanceof Literal lit) || l.hearsBeliefEvent(op, lit)) {
                return false;
            }
        }
        return true;
    }

    public void addEvent(Event e) {
        // as Jason's updateEvents: an external belief event no plan is relevant for is not kept,
        // unless a listener hears such events (a .wait for it, an inspector); a message told or a
        // -+b then costs no event to select and discard
        if (e.intention() == null && e.trigger().type() == Trigger.Type.BELIEF && relevant != null
                && !relevant.test(e.trigger()) && unheard(e.trigger().op(), e.trigger().literal())) {
            return;
        }
        keep(e);
    }

    private void keep(Event e) {
        if (e.isAtomic()) {
            atomicEvent = e;
        } else {
            events.add(e);
        }
        if (goalStates != null) {
            goalStates.eventAdded(e);
        }
        for (CircumstanceListener l : listeners) {
            l.eventAdded(e);
        }
    }

    /** Adds a meta-event ahead of the other events, after the meta-events already there (Jason's rule). */
    void insertMetaEvent(Event e) {
        var rest = new ArrayList<Event>();
        while (!events.isEmpty() && events.peekFirst().trigger().op() == Trigger.Op.GOAL_STATE) {
            rest.add(events.pollFirst());
        }
        rest.add(e);
        for (int k = rest.size() - 1; k >= 0; k--) {
            events.addFirst(rest.get(k));
        }
        if (goalStates != null) {
            goalStates.eventAdded(e);
        }
        for (CircumstanceListener l : listeners) {
            l.eventAdded(e);
        }
    }

    Event pollAtomicEvent() {
        Event e = atomicEvent;
        atomicEvent = null;
        return e;
    }

    public boolean hasEvent() {
        return !events.isEmpty() || atomicEvent != null;
    }

    ArrayDeque<Event> events() {
        return events;
    }

    /** {@return a snapshot of the pending events} */
    public List<Event> eventList() {
        var out = new ArrayList<Event>(events);
        if (atomicEvent != null) {
            out.add(0, atomicEvent);
        }
        return out;
    }

    public boolean removeEvent(Event e) {
        if (e == atomicEvent) {
            atomicEvent = null;
            return true;
        }
        return events.remove(e);
    }

    void setSelectedEvent(Event e) {
        selectedEvent = e;
    }

    void setSelectedIntention(Intention i) {
        selectedIntention = i;
    }

    ActionExec action() {
        return action;
    }

    void setAction(ActionExec a) {
        action = a;
    }

    public Event selectedEvent() {
        return selectedEvent;
    }

    // ---- running intentions (I) -------------------------------------------------------------------

    public void addRunningIntention(Intention i) {
        if (i.isAtomic()) {
            atomicIntention = i;
        } else {
            running.offer(i);
        }
        if (i.hasGoalCondition()) {
            intentionsWithGoalCondition++;
        }
        for (CircumstanceListener l : listeners) {
            l.intentionAdded(i);
        }
    }

    /**
     * Intentions with a goal condition added to I since the last look found none (Jason's count):
     * the cycle tests goal conditions only while some may be pending.
     */
    private int intentionsWithGoalCondition;

    boolean hasIntentionWithGoalCondition() {
        return intentionsWithGoalCondition > 0;
    }

    void resetIntentionsWithGoalCondition() {
        intentionsWithGoalCondition = 0;
    }

    Intention pollRunningIntention() {
        return running.poll();
    }

    Intention takeAtomicIntention() {
        if (atomicIntention == null || atomicIntentionSuspended) {
            return null;
        }
        Intention i = atomicIntention;
        atomicIntention = null;
        return i;
    }

    public boolean hasAtomicIntention() {
        return atomicIntention != null;
    }

    boolean isAtomicIntentionSuspended() {
        return atomicIntention != null && atomicIntentionSuspended;
    }

    public boolean hasRunningIntention() {
        return !running.isEmpty() || (atomicIntention != null && !atomicIntentionSuspended);
    }

    public boolean hasRunningIntention(Intention i) {
        return running.contains(i) || atomicIntention == i;
    }

    /** Removes an intention from I. {@return whether it was there} */
    public boolean removeRunningIntention(Intention i) {
        if (i == atomicIntention) {
            atomicIntention = null;
            atomicIntentionSuspended = false;
            return true;
        }
        return running.remove(i);
    }

    /**
     * {@return every intention: selected, running, pending, and those waiting in events or actions,
     * the selected event's too (a plan's context may ask for the goals of the intention it is for)}
     */
    public List<Intention> allIntentions() {
        var out = new ArrayList<Intention>();
        if (selectedIntention != null) {
            out.add(selectedIntention);
        }
        if (selectedEvent != null && selectedEvent.intention() != null && !out.contains(selectedEvent.intention())) {
            out.add(selectedEvent.intention());
        }
        if (atomicIntention != null && !out.contains(atomicIntention)) {
            out.add(atomicIntention);
        }
        for (Intention i : running) {
            if (!out.contains(i)) {
                out.add(i);
            }
        }
        for (Pending p : pending.values()) {
            if (!out.contains(p.intention())) {
                out.add(p.intention());
            }
        }
        for (ActionExec a : pendingActions.values()) {
            if (!out.contains(a.intention())) {
                out.add(a.intention());
            }
        }
        for (Event e : eventList()) {
            if (e.intention() != null && !out.contains(e.intention())) {
                out.add(e.intention());
            }
        }
        return out;
    }

    public Collection<Intention> runningIntentions() {
        return List.copyOf(running);
    }

    public Intention selectedIntention() {
        return selectedIntention;
    }

    // ---- pending intentions (PI) ------------------------------------------------------------------

    /** Suspends an intention; an atomic one stays the atomic intention, so nothing else runs meanwhile. */
    public void addPendingIntention(String key, Term reason, Intention i) {
        holdIfAtomic(i);
        pending.put(key, new Pending(i, reason));
    }

    /** A waiting atomic intention (in PI or PA) stays the atomic intention, suspended: it holds the agent (Jason's rule). */
    private void holdIfAtomic(Intention i) {
        if (i.isAtomic()) {
            atomicIntention = i;
            atomicIntentionSuspended = true;
        }
    }

    private void releaseIfAtomic(Intention i) {
        if (i.isAtomic()) {
            atomicIntentionSuspended = false;
        }
    }

    /**
     * {@return why an intention waits, as Jason's {@code .intention} tells: its reason in PI
     * ({@code wait(Id)[time(T)]}, ...), or {@code action(A)} for an action whose feedback it waits
     * for; null when it does not wait there}
     */
    public Literal waitingReason(Intention i) {
        for (Pending p : pending.values()) {
            if (p.intention() == i) {
                return Literal.of("reason", p.reason());
            }
        }
        ActionExec a = pendingActions.get(i.id());
        return a != null && a.intention() == i ? Literal.of("action", a.action()) : null;
    }

    public Intention removePendingIntention(String key) {
        Pending p = pending.remove(key);
        if (p == null) {
            return null;
        }
        releaseIfAtomic(p.intention());
        return p.intention();
    }

    public void addPendingEvent(String key, Event e) {
        pendingEvents.put(key, e);
    }

    public Event removePendingEvent(String key) {
        return pendingEvents.remove(key);
    }

    public Map<String, Event> pendingEvents() {
        return Collections.unmodifiableMap(new LinkedHashMap<>(pendingEvents));
    }

    public Map<String, Pending> pendingIntentions() {
        return Collections.unmodifiableMap(new LinkedHashMap<>(pending));
    }

    /** Removes every pending entry of an intention. {@return whether there was one} */
    boolean removePendingEntriesOf(Intention i) {
        return pending.values().removeIf(p -> p.intention() == i);
    }

    // ---- actions (PA, FA) ----------------------------------------------------------------------------

    void addPendingAction(ActionExec a) {
        holdIfAtomic(a.intention());
        pendingActions.put(a.intention().id(), a);
    }

    ActionExec removePendingAction(int intentionId) {
        ActionExec a = pendingActions.remove(intentionId);
        if (a != null) {
            releaseIfAtomic(a.intention());
        }
        return a;
    }

    List<Intention> pendingActionIntentions() {
        var out = new ArrayList<Intention>();
        pendingActions.values().forEach(a -> out.add(a.intention()));
        return out;
    }

    boolean removePendingActionOf(Intention i) {
        return removePendingAction(i.id()) != null;
    }

    /** Called by the architecture (any thread) when an action has been executed. */
    public void addFeedbackAction(ActionExec a) {
        feedback.add(a);
    }

    ActionExec pollFeedbackAction() {
        return feedback.poll();
    }

    public boolean hasFeedbackAction() {
        return !feedback.isEmpty();
    }

    // ---- mailbox (MB) -----------------------------------------------------------------------------

    /** Called by the infrastructure (any thread) to deliver a message. */
    public void addMessage(Message m) {
        synchronized (mailbox) {
            mailbox.addLast(m);
            mailboxSize = mailbox.size();
        }
    }

    Message pollMessage() {
        if (mailboxSize == 0) {
            return null;
        }
        synchronized (mailbox) {
            Message m = mailbox.pollFirst();
            mailboxSize = mailbox.size();
            return m;
        }
    }

    /** {@return how many messages wait in the mailbox} */
    public int messageCount() {
        return mailboxSize;
    }

    public boolean hasMessage() {
        return mailboxSize > 0;
    }

    // ---- listeners ----------------------------------------------------------------------------------

    public void addListener(CircumstanceListener l) {
        listeners = Arrays.copyOf(listeners, listeners.length + 1);
        listeners[listeners.length - 1] = l;
    }

    public void removeListener(CircumstanceListener l) {
        for (int k = 0; k < listeners.length; k++) {
            if (listeners[k].equals(l)) {
                var rest = new CircumstanceListener[listeners.length - 1];
                System.arraycopy(listeners, 0, rest, 0, k);
                System.arraycopy(listeners, k + 1, rest, k, rest.length - k);
                listeners = rest;
                return;
            }
        }
    }

    void notifyDropped(Intention i) {
        for (CircumstanceListener l : listeners) {
            l.intentionDropped(i);
        }
    }
}
