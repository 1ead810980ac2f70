package jacabot.agent.semantics;

import jacabot.agent.parser.AslParser;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A BDI agent: beliefs, plans, circumstance and the reasoning cycle that runs them. All of its
 * state is its own (no statics): ids, fresh variables, timers and the random generator.
 *
 * <p>Thread model: one thread at a time runs {@link #reasoningCycle()}; other threads talk to the
 * agent only through {@link #actionExecuted}, {@link #deliver(Message)} and
 * {@link #runAtBeginOfNextCycle(Runnable)}, which are thread-safe.
 */
public final class Agent {
    private final String name;
    private final AgentArch arch;
    private final BeliefBase beliefBase = new BeliefBase();
    private final PlanLibrary planLibrary = new PlanLibrary();
    private final Circumstance circumstance = new Circumstance();
    private final GoalStates goalStates = new GoalStates(this);
    private volatile int verbosity = 1;
    private boolean sleepingEvent;
    /** External events posted by other threads (the infrastructure), taken in at the next sense. */
    private final ConcurrentLinkedQueue<Event> incoming = new ConcurrentLinkedQueue<>();
    private final Solver solver = new Solver(this);
    private final ReasoningCycle cycle = new ReasoningCycle(this);
    private final Map<String, InternalAction> internalActions;
    private final ArithEvaluator arith = new ArithEvaluator(this);
    private final CycleTasks cycleTasks = new CycleTasks();
    private final Set<Literal> perceptBeliefs = new HashSet<>();
    private final AslParser parser;
    private Random random;
    private long freshSerial;
    /** Intention numbers: one counter for the whole system, as Jason's is one per JVM. */
    private AtomicInteger intentionSerial = new AtomicInteger();
    private AtomicInteger messageSerial = new AtomicInteger();
    private long cycles;
    private volatile boolean stopped;
    private PlanListener planListener;

    public void setPlanListener(PlanListener listener) {
        this.planListener = listener;
    }

    PlanListener planListener() {
        return planListener;
    }

    private UnhandledFailureListener unhandledFailureListener;

    public void setUnhandledFailureListener(UnhandledFailureListener listener) {
        this.unhandledFailureListener = listener;
    }

    UnhandledFailureListener unhandledFailureListener() {
        return unhandledFailureListener;
    }

    public Agent(String name, AgentArch arch, Map<String, InternalAction> internalActions, long seed,
            AslParser parser) {
        this.name = name;
        this.arch = arch;
        this.internalActions = internalActions;
        this.random = new Random(seed);
        this.parser = parser;
        circumstance.own(goalStates, planLibrary::hasCandidate,
                (op, l) -> planLibrary.hasCandidate(op, Trigger.Type.BELIEF, l));
    }

    /** {@return the goal states, which post {@code ^!g[state(S)]} meta-events} */
    public GoalStates goalStates() {
        return goalStates;
    }

    /** Loads a program: initial beliefs (with their events), rules, plans and initial goals. */
    public void load(AgentProgram program) {
        program.functions().forEach(arith::register);
        for (Plan p : program.plans()) {
            planLibrary.add(withUrl(p), false);
        }
        // As Jason: initial beliefs are added last to first at the beginning of the belief base,
        // so the base keeps file order and their +b events come in reverse order.
        List<Object> beliefs = program.beliefs();
        for (int k = beliefs.size() - 1; k >= 0; k--) {
            Object b = beliefs.get(k);
            if (b instanceof Rule r) {
                Literal head = r.head().hasSource() ? r.head() : r.head().addAnnot(Literal.SOURCE_SELF);
                beliefBase.addRule(new Rule(head, r.body()), false);
            } else {
                Literal l = (Literal) b;
                Literal bel = l.hasSource() ? l : l.addAnnot(Literal.SOURCE_SELF);
                Literal added = beliefBase.add(bel, false);
                if (added != null) {
                    circumstance.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, added), null));
                }
            }
        }
        for (Literal g : program.goals()) {
            // as Jason, a goal's variables are renamed apart (they take numbers of its one counter)
            g = g.isGround() ? g : (Literal) Renamer.renameApart(g, this);
            Literal goal = g.hasSource() ? g : g.addAnnot(Literal.SOURCE_SELF);
            circumstance.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, goal), null));
        }
    }

    /** Jason marks a plan read from a file with {@code url("file:...")} in its label. */
    private static Plan withUrl(Plan p) {
        if (p.source() == null || p.source().file().isEmpty()) {
            return p;
        }
        Literal label = p.label() == null ? Literal.atom("undefined") : p.label();
        if (label.getAnnot("url") != null) {
            return p;
        }
        return p.withLabel(label.addAnnot(Literal.of("url", new StringTerm(p.source().jasonFile()))));
    }

    // ---- the reasoning cycle ------------------------------------------------------------------

    /** Runs one reasoning cycle (sense, deliberate, act). */
    public void reasoningCycle() {
        cycles++;
        cycle.run();
    }

    /**
     * Jason's idle events: {@code +jag_sleeping} when the agent has nothing left to do,
     * {@code +jag_awaking} when something comes again (posted in sense, only when plans react).
     */
    void senseIdleness() {
        Event e;
        while ((e = incoming.poll()) != null) {
            circumstance.addEvent(e);
        }
        if (!planLibrary.hasJagPlans()) {
            return;
        }
        if (nothingToDo()) {
            if (!sleepingEvent) {
                sleepingEvent = true;
                circumstance.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, Literal.atom("jag_sleeping")), null));
            }
        } else if (sleepingEvent) {
            sleepingEvent = false;
            circumstance.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, Literal.atom("jag_awaking")), null));
        }
    }

    /** Jason's TransitionSystem.canSleep: no event, intention, feedback, message or task. */
    private boolean nothingToDo() {
        if (circumstance.isAtomicIntentionSuspended()) {
            return !circumstance.hasFeedbackAction() && !circumstance.hasMessage();
        }
        return !circumstance.hasEvent() && !circumstance.hasRunningIntention() && !circumstance.hasFeedbackAction()
                && !circumstance.hasMessage() && cycleTasks.isEmpty() && arch.canSleep();
    }

    /** Posts an external event from any thread (e.g. {@code +jag_shutting_down(T)}); it joins E at the next sense. */
    public void postExternalEvent(Event e) {
        incoming.add(e);
        arch.wake();
    }

    /** {@return whether a cycle now would do nothing (the agent may sleep until woken)} */
    public boolean canSleep() {
        if (!incoming.isEmpty()) {
            return false;
        }
        if (planLibrary.hasJagPlans() && !sleepingEvent && nothingToDo()) {
            return false; // one more cycle, to post +jag_sleeping
        }
        // the common case first: work is waiting (unless an atomic intention holds the agent)
        if (!circumstance.isAtomicIntentionSuspended()
                && (circumstance.hasEvent() || circumstance.hasRunningIntention())) {
            return false;
        }
        if (!cycleTasks.isEmpty() || circumstance.hasMessage() || circumstance.hasFeedbackAction()
                || !arch.canSleep()) {
            return false;
        }
        if (nextTimerDue() <= clock().millis()) {
            return false;
        }
        if (circumstance.isAtomicIntentionSuspended()) {
            return true;
        }
        return !circumstance.hasEvent() && !circumstance.hasRunningIntention();
    }

    /** {@return when the earliest timer is due, or {@code Long.MAX_VALUE}} */
    public long nextTimerDue() {
        return cycleTasks.nextDue();
    }

    public long cycles() {
        return cycles;
    }

    public boolean isStopped() {
        return stopped;
    }

    public void stop() {
        stopped = true;
    }

    /** Schedules a task for the start of the next cycle's deliberation (any thread). */
    public void runAtBeginOfNextCycle(Runnable task) {
        cycleTasks.add(task);
        arch.wake();
    }

    void runBeginOfCycleTasks() {
        cycleTasks.runAll();
    }

    /** Runs {@code task} at the start of a cycle once the clock reaches {@code due} (ms). */
    public void schedule(long due, Runnable task) {
        cycleTasks.schedule(due, task);
    }

    /** Fires the timers that are due: their tasks run at the start of this cycle's deliberation. */
    void fireDueTimers() {
        cycleTasks.fireDue(clock());
    }

    // ---- architecture callbacks (thread-safe) ------------------------------------------------

    /** Called by the architecture when an environment action has finished (any thread). */
    public void actionExecuted(ActionExec action) {
        circumstance.addFeedbackAction(action);
        arch.wake();
    }

    /** Delivers a message to this agent's mailbox (any thread). */
    public void deliver(Message m) {
        circumstance.addMessage(m);
        arch.wake();
    }

    // ---- accessors ----------------------------------------------------------------------------

    public String name() {
        return name;
    }

    public AgentArch arch() {
        return arch;
    }

    public BeliefBase beliefBase() {
        return beliefBase;
    }

    public PlanLibrary planLibrary() {
        return planLibrary;
    }

    public Circumstance circumstance() {
        return circumstance;
    }

    public Solver solver() {
        return solver;
    }

    public Clock clock() {
        return arch.clock();
    }

    public Random random() {
        return random;
    }

    public void setRandomSeed(long seed) {
        random = new Random(seed);
    }

    public AslParser parser() {
        return parser;
    }

    ReasoningCycle cycle() {
        return cycle;
    }

    public InternalAction internalAction(String functor) {
        return internalActions.get(functor);
    }

    /**
     * Adds a library's internal action (JaCa's {@code cartago.*} come with its architecture);
     * on the agent's thread, before a plan uses it.
     */
    public void addInternalAction(String name, InternalAction ia) {
        internalActions.put(name, ia);
    }

    /**
     * {@return a variable no other has, for a renaming Jason does not make (its number is not one
     * of the counter's: Jason's would not have been taken)}
     */
    Var internalVar(Var like) {
        internalTaken++;
        return new Var(like.name(), -(++freshSerial));
    }

    /** The variables {@link #freshVar} and {@link #internalVar} made so far (for {@link FailedQueries}). */
    private long freshTaken, internalTaken;

    long freshTaken() {
        return freshTaken;
    }

    long internalTaken() {
        return internalTaken;
    }

    /** Takes the numbers {@code fresh} calls of {@link #freshVar} and {@code internal} of {@link #internalVar} would take. */
    void retakeVars(long fresh, long internal) {
        if (fresh > 0) {
            freshSerials(Math.toIntExact(fresh));
        }
        freshSerial += internal;
        internalTaken += internal;
    }

    /** Takes the numbers {@code n} fresh variables would take (where Jason makes variables that nobody sees). */
    void skipFreshVars(int n) {
        if (parser != null) {
            parser.varCounter().addAndGet(n);
        } else {
            freshSerial += n;
        }
    }

    /** Takes the numbers of {@code n} fresh variables, at once (the one place that counts them). {@return the first of them} */
    long freshSerials(int n) {
        freshTaken += n;
        if (parser != null) {
            return parser.varCounter().getAndAdd(n) + 1;
        }
        long first = freshSerial + 1;
        freshSerial += n;
        return first;
    }

    /**
     * {@return a variable no other has, for renaming apart} Its number comes from the counter its
     * parser shares with the other agents of the system, as Jason's unnamed variables ({@code _41})
     * come from one counter.
     */
    public Var freshVar(Var like) {
        return new Var(like.name(), freshSerials(1));
    }

    /** {@return a copy of an intention, with its own id and unifiers, not yet running (a branch of {@code .fork})} */
    public Intention copyIntention(Intention i) {
        return i.copyAs(nextIntentionId());
    }

    int nextIntentionId() {
        return intentionSerial.incrementAndGet();
    }

    /** Numbers this agent's intentions from {@code counter}, shared with the other agents of its system. */
    public void shareIntentionCounter(AtomicInteger counter) {
        intentionSerial = counter;
    }

    public String nextMessageId() {
        return Message.idOf(nextMessageSerial());
    }

    /** {@return the number of the agent's next message, whose id is {@code mid}N} */
    public int nextMessageSerial() {
        return messageSerial.incrementAndGet();
    }

    /** Numbers this agent's messages from {@code counter}, shared with the other agents of its system (Jason's are JVM-wide). */
    public void shareMessageCounter(AtomicInteger counter) {
        messageSerial = counter;
    }

    /** {@return a unifier that evaluates this agent's arithmetic functions} */
    public Unifier newUnifier() {
        var u = new Unifier();
        u.setEvaluator(arith);
        return u;
    }

    /** Applies the unifier to the arguments, unless the action takes them raw. */
    public Term[] prepareArguments(InternalAction ia, Literal l, Unifier u) throws IaException {
        int n = l.arity();
        if (n < ia.minArgs() || n > ia.maxArgs()) {
            throw IaException.wrongArgumentCount(l.functor(), ia.minArgs(), ia.maxArgs());
        }
        if (!ia.appliesArguments()) {
            // a loop's step comes back every turn: its arguments as they are, in the same array
            PlainArgs last = plainArgs;
            if (last.formula() != l) {
                last = new PlainArgs(l, l.args().toArray(new Term[n]));
                plainArgs = last;
            }
            return last.args();
        }
        Term[] args = new Term[n];
        for (int i = 0; i < n; i++) {
            args[i] = u.apply(l.arg(i));
        }
        return args;
    }

    /** A formula given to an action that takes its arguments as they are, and those arguments. */
    private record PlainArgs(Literal formula, Term[] args) {
    }

    /** The last {@link PlainArgs}, in one field: a solver may run on another thread too. */
    private PlainArgs plainArgs = new PlainArgs(null, new Term[0]);

    // ---- console ------------------------------------------------------------------------------

    /**
     * Prints a console line as {@code [name] text}, as Jason's console does; with the project
     * option {@code verbose=0} Jason's log shows warnings only and {@code .print} writes the bare text.
     */
    public void print(String text) {
        arch.console(verbosity == 0 ? text : "[" + name + "] " + text);
    }

    /** Jason's {@code verbose} agent option: 0 warnings only, 1 (default) information, 2 details. */
    public void setVerbosity(int level) {
        verbosity = level;
    }

    /** Prints a warning on the console, in the same form. */
    public void warn(String text) {
        arch.console("[" + name + "] " + text);
    }

    // ---- belief revision --------------------------------------------------------------------

    /**
     * Adds a belief. {@return the literal of the {@code +b} event, or null when nothing changed}
     */
    public Literal addBelief(Literal l, boolean atEnd) {
        return beliefBase.add(l, atEnd);
    }

    /**
     * Removes the first belief matching {@code l} (annotations as a subset): its annotations in
     * {@code l} go, and the belief goes when it has no source left. {@return the removed part}
     */
    public Literal removeBelief(Literal l, Unifier u) {
        Literal q = (Literal) u.apply(l);
        if (q.isGround()) {
            // the usual case, -b(1): find the fact by its arguments
            Literal removed = beliefBase.removeFact(q);
            if (removed != null) {
                return removed;
            }
        }
        // the loop ends before the belief base changes, so it may go through the entries as they are
        for (BeliefBase.Entry e : q.ns() instanceof Var ? beliefBase.candidates(q) : beliefBase.current(q)) {
            if (e.rule() != null) {
                continue;
            }
            // a failed unification binds nothing, so u itself can try each candidate
            if (u.unifies(q, e.literal())) {
                return beliefBase.remove(e.literal(), (Literal) u.apply(q));
            }
        }
        return null;
    }

    /** Jason's default belief update: percepts replace the beliefs with {@code source(percept)}. */
    public void beliefUpdate(List<Literal> percepts) {
        var now = new HashSet<Literal>();
        for (Literal p : percepts) {
            now.add(p.hasSource() ? p : p.addAnnot(Literal.SOURCE_PERCEPT));
        }
        for (Iterator<Literal> it = perceptBeliefs.iterator(); it.hasNext();) {
            Literal old = it.next();
            if (!now.contains(old)) {
                it.remove();
                if (beliefBase.remove(old, Literal.of("x").withAnnots(List.of(Literal.SOURCE_PERCEPT))) != null) {
                    circumstance.addEvent(new Event(new Trigger(Trigger.Op.DEL, Trigger.Type.BELIEF, old), null));
                }
            }
        }
        for (Literal p : now) {
            if (perceptBeliefs.add(p)) {
                Literal added = beliefBase.add(p, false);
                if (added != null) {
                    circumstance.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, added), null));
                }
            }
        }
    }

    /**
     * Adds a belief from the environment (e.g. an observable property) with a {@code +b} event;
     * call from the agent's cycle. {@return whether the belief base changed}
     */
    public boolean addPercept(Literal l) {
        Literal added = beliefBase.add(l, false);
        if (added != null) {
            circumstance.addBeliefEvent(Trigger.Op.ADD, added);
        }
        return added != null;
    }

    /** Removes a belief added by {@link #addPercept} with a {@code -b} event. */
    public boolean removePercept(Literal l) {
        if (beliefBase.removeEntry(l)) {
            circumstance.addBeliefEvent(Trigger.Op.DEL, l);
            return true;
        }
        return false;
    }

    /** Adds an external event (e.g. a signal from an artifact); call from the agent's cycle. */
    public void addExternalEvent(Trigger trigger) {
        circumstance.addEvent(new Event(trigger, null));
    }

    /** {@return the intentions that have an intended means for goal {@code g}} */
    public List<Intention> intentionsFor(Literal g, Unifier u) {
        var out = new ArrayList<Intention>();
        for (Intention i : circumstance.allIntentions()) {
            if (i.hasGoal(g, u)) {
                out.add(i);
            }
        }
        return out;
    }

    /** Drops an intention from everywhere it may be (I, PI, PA, events). */
    public void dropIntention(Intention i) {
        boolean removed = circumstance.removeRunningIntention(i);
        removed |= circumstance.removePendingEntriesOf(i);
        removed |= circumstance.removePendingActionOf(i);
        for (Event e : circumstance.eventList()) {
            if (e.intention() == i) {
                circumstance.removeEvent(e);
                removed = true;
            }
        }
        if (circumstance.selectedIntention() == i) {
            cycle.dropSelected();
            removed = true;
        }
        if (removed) {
            circumstance.notifyDropped(i);
        }
    }

    /** Keeps the running intention out of the queue after the current internal action. */
    public void holdSelectedIntention() {
        cycle.holdSelected();
    }

    /** ClrInt on an intention (after goals were removed from it). */
    public void clearIntention(Intention i) {
        cycle.applyClrInt(i);
    }

    /** {@return the failure event for a goal of the intention, or null when no plan handles it} */
    public Event failureEventFor(Intention i, Trigger goal) {
        return cycle.findEventForFailure(i, goal);
    }

    /** Generates the failure of the intention's current goal, as Jason's goal deletion. */
    public boolean failIntention(Intention i, String errorId, String message) {
        return cycle.generateGoalDeletion(i, ReasoningCycle.errorAnnots(errorId, message));
    }

    public List<Plan> plans() {
        return Collections.unmodifiableList(planLibrary.plans());
    }
}
