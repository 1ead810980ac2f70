package jacabot.agent.runtime;

import jacabot.agent.semantics.Clock;
import jacabot.agent.parser.AslParser;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.AgentArch;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.InternalAction;
import jacabot.agent.semantics.Message;
import jacabot.agent.stdlib.Stdlib;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Trigger;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BiConsumer;
import java.util.function.Function;

/**
 * Jason's local infrastructure: agents in one JVM, messages by direct delivery, one console.
 *
 * <p>Two ways to run. {@link #runThreads()}: each agent on its own thread, free running, sleeping
 * when it has nothing to do (Jason's default). {@link #runUntilQuiescent(long)} and
 * {@link #runStepping()}: one thread runs the agents' cycles in a fixed round-robin order, so the
 * same program and seed give the same run (used for lockstep simulation and tests).
 */
public final class LocalMAS {
    private final Map<String, Agent> agents = new LinkedHashMap<>();
    private final Map<String, Waker> wakers = new ConcurrentHashMap<>();
    private volatile boolean threadsRunning;
    private final DirectoryFacilitator df = new DirectoryFacilitator(this::deliver);
    private volatile Clock clock;
    private final PrintStream out;
    private final long seed;
    private Environment environment = new DefaultEnvironment();
    private final ReentrantLock stepLock = new ReentrantLock();
    private final Condition stepCondition = stepLock.newCondition();
    private volatile boolean stopped;
    private volatile boolean wokenInStepping;
    /** Whether the stepping thread waits (or is about to): only then does a wake take its lock. */
    private volatile boolean steppingAsleep;
    private final CountDownLatch finished = new CountDownLatch(1);
    /** In {@link #runSimulated}: the time {@code .stopMAS(T)} stops the system at (else a thread sleeps T). */
    private volatile long simulatedStopDue = Long.MAX_VALUE;
    private volatile SimulatedTime simulatedTime;
    /** Stepping: told of an agent whose reasoning cycle threw; null: the throw ends the step. */
    private volatile BiConsumer<String, Throwable> onAgentDied;

    /**
     * Wakes one sleeping agent thread. The sleeper raises {@code asleep} before it checks for
     * work and a waker raises {@code woken} before it checks {@code asleep}, so one of them sees
     * the other: a busy agent is woken without a lock, and a sleeping one is never missed. The
     * sleeper parks and the waker unparks it, with no lock: an unpark that comes before the park
     * makes the park return at once. (With a lock and its condition, a sender of a message
     * stream took the lock at nearly every message, the receiver catching up and raising asleep
     * each time, and each waited for the other.)
     */
    private static final class Waker {
        final Agent agent;
        /** The agent's thread, once it runs. */
        volatile Thread thread;
        volatile boolean woken;
        volatile boolean asleep;

        Waker(Agent agent) {
            this.agent = agent;
        }
    }

    public LocalMAS(Clock clock, PrintStream out, long seed) {
        this.clock = clock;
        this.out = out;
        this.seed = seed;
    }

    public LocalMAS() {
        this(Clock.wall(), System.out, 0);
    }

    public void setEnvironment(Environment environment, List<String> args) {
        this.environment = environment;
        environment.init(this, args);
    }

    public Environment environment() {
        return environment;
    }

    public Clock clock() {
        return clock;
    }

    /**
     * Replaces the agents' clock, e.g. by one that follows a simulation's time; to be called before
     * the agents run (environments do it in {@link Environment#init}).
     */
    public void useClock(Clock newClock) {
        this.clock = newClock;
    }

    /** The p__N numbers of unnamed plans go on from agent to agent in load order, as in Jason. */
    private final AtomicInteger planLabels = new AtomicInteger();
    /** So do the numbers of intentions, in the order they are created. */
    private final AtomicInteger intentionIds = new AtomicInteger();
    /** And the numbers of messages (mid N), in the order they are sent. */
    private final AtomicInteger messageIds = new AtomicInteger();

    /**
     * Creates an agent running a program. {@code archFactory} may wrap the local architecture
     * (e.g. the JaCa bridge); null keeps it.
     */
    /** The unnamed variables ({@code _}) in Jason 3.2's {@code kqmlPlans.asl}, which each Jason agent reads. */
    static final int JASON_KQML_PLANS_UNNAMED_VARS = 18;

    /**
     * {@return {@code name} when no agent has it, else Jason's next free one: {@code name_1},
     * {@code name_2}, ... (Jason 3.2.0's RuntimeServices.getNewAgentName, for a project's agents
     * and for {@code .create_agent})}
     */
    public synchronized String newAgentName(String name) {
        String free = name;
        for (int i = 1; agents.containsKey(free); i++) {
            free = name + "_" + i;
        }
        return free;
    }

    public synchronized Agent createAgent(String name, AgentProgram program, AslParser parser,
            Function<LocalArch, AgentArch> archFactory) {
        if (agents.containsKey(name)) {
            throw new IllegalArgumentException("an agent named '" + name + "' already exists");
        }
        LocalArch local = new LocalArch(this, name);
        AgentArch arch = archFactory == null ? local : archFactory.apply(local);
        Map<String, InternalAction> ias = Stdlib.defaults();
        Agent ag = new Agent(name, arch, ias, agentSeed(seed, agents.size()), parser);
        ag.planLibrary().shareLabelCounter(planLabels);
        ag.shareIntentionCounter(intentionIds);
        ag.shareMessageCounter(messageIds);
        agents.put(name, ag);
        wakers.put(name, new Waker(ag));
        ag.load(program);
        if (parser != null) {
            // Jason's agent then reads its kqmlPlans.asl, whose 18 unnamed variables take numbers
            // of the counter of fresh variables (ours are built in): the next numbers are Jason's
            parser.varCounter().addAndGet(JASON_KQML_PLANS_UNNAMED_VARS);
        }
        return ag;
    }

    /**
     * Each agent's own random stream, reproducible under one seed. java.util.Random's first draws
     * for seeds n, n+1, ... are nearly alike, so the index is mixed in (SplitMix64's finaliser).
     * The first agent keeps the seed itself, so a one-agent run (the experiments) replays as before.
     */
    static long agentSeed(long seed, int index) {
        if (index == 0) {
            return seed;
        }
        long z = seed + (index + 1) * 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    public synchronized Agent agent(String name) {
        return agents.get(name);
    }

    public synchronized List<String> agentNames() {
        return new ArrayList<>(agents.keySet());
    }

    private synchronized List<Agent> agentList() {
        return new ArrayList<>(agents.values());
    }

    DirectoryFacilitator df() {
        return df;
    }

    boolean deliver(Message m) {
        // the concurrent map, not the synchronized agent(name): every agent's messages come here
        Waker w = wakers.get(m.receiver());
        if (w == null) {
            return false;
        }
        w.agent.deliver(m);
        return true;
    }

    /** Prints a console line; lines of different agents never interleave. */
    public void console(String line) {
        synchronized (out) {
            out.println(line);
            out.flush();
        }
    }

    /** {@return the stream console lines go to (e.g. for an artifact console)} */
    public PrintStream consoleStream() {
        return out;
    }

    public boolean isStopped() {
        return stopped;
    }

    /** Stops every agent ({@code .stopMAS}); the run methods return. */
    /** Jason's {@code .stopMAS(T)}: every agent gets {@code +jag_shutting_down(T)}, and the system stops T ms later. */
    public void stopIn(long deadlineMs) {
        var event = new Event(new Trigger(Trigger.Op.ADD,
                Trigger.Type.BELIEF, Literal.of("jag_shutting_down",
                        new NumberTerm(deadlineMs))), null);
        for (Agent a : agentList()) {
            a.postExternalEvent(event);
        }
        SimulatedTime time = simulatedTime;
        if (time != null) {
            simulatedStopDue = Math.min(simulatedStopDue, time.millis() + deadlineMs);
            return;
        }
        Thread timer = new Thread(() -> {
            try {
                Thread.sleep(deadlineMs);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            stop();
        }, "stopMAS-deadline");
        timer.setDaemon(true);
        timer.start();
    }

    public void stop() {
        stopped = true;
        for (Agent a : agentList()) {
            a.stop();
        }
        for (String name : wakers.keySet()) {
            wake(name);
        }
        wakeStepping();
        environment.stop();
        finished.countDown();
    }

    void wake(String name) {
        Waker w = wakers.get(name);
        if (w != null) {
            // raised only when down: a message stream to a busy agent then writes nothing that
            // its thread reads (a woken still raised is the sleeper's to see and lower)
            if (!w.woken) {
                w.woken = true;
            }
            if (w.asleep) {
                LockSupport.unpark(w.thread);
            }
        }
        wakeStepping();
    }

    private void wakeStepping() {
        // as a waker's woken: written when down only, since agent threads read the fields around it
        if (!wokenInStepping) {
            wokenInStepping = true;
        }
        if (steppingAsleep) {
            stepLock.lock();
            try {
                stepCondition.signalAll();
            } finally {
                stepLock.unlock();
            }
        }
    }

    // ---- stepping ---------------------------------------------------------------------------------

    /**
     * Runs reasoning cycles, agent after agent in a fixed order, until every agent can sleep or
     * {@code budget} cycles have run. {@return the number of cycles run}
     */
    public long runUntilQuiescent(long budget) {
        long run = 0;
        List<Agent> list = agentList();
        boolean any = true;
        while (any && run < budget && !stopped) {
            any = false;
            for (Agent a : list) {
                if (stopped || run >= budget) {
                    break;
                }
                if (!a.isStopped() && !a.canSleep()) { // a killed agent may be in the list taken before
                    run++;
                    any = true;
                    cycleOrDie(a);
                }
            }
        }
        return run;
    }

    /**
     * Stepping: an agent whose reasoning cycle throws (an exception, a runaway recursion) is taken out
     * of the system, as by {@code .kill_agent}, and {@code listener} is told; the other agents go on.
     * Without a listener (the default) the throw ends {@link #runUntilQuiescent}, as before. Not in
     * Jason, whose agent threads log the error and go on: a team's host wants the agent gone, so that
     * its robot stops and what it held is freed.
     */
    public void onAgentDied(BiConsumer<String, Throwable> listener) {
        this.onAgentDied = listener;
    }

    private void cycleOrDie(Agent a) {
        BiConsumer<String, Throwable> died = onAgentDied;
        if (died == null) {
            a.reasoningCycle();
            return;
        }
        try {
            a.reasoningCycle();
        } catch (RuntimeException | StackOverflowError e) {
            kill(a.name());
            died.accept(a.name(), e);
        }
    }

    /** Runs in stepping mode until {@code .stopMAS}, sleeping while every agent is idle. */
    public void runStepping() throws InterruptedException {
        while (!stopped) {
            runUntilQuiescent(Long.MAX_VALUE);
            if (stopped) {
                break;
            }
            long due = Long.MAX_VALUE;
            for (Agent a : agentList()) {
                due = Math.min(due, a.nextTimerDue());
            }
            stepLock.lock();
            try {
                steppingAsleep = true;
                if (!wokenInStepping) {
                    long wait = due == Long.MAX_VALUE ? 1000 : Math.max(0, due - clock.millis());
                    if (wait > 0) {
                        stepCondition.await(wait, TimeUnit.MILLISECONDS);
                    }
                }
                wokenInStepping = false;
            } finally {
                steppingAsleep = false;
                stepLock.unlock();
            }
        }
    }

    /**
     * Runs in stepping mode on simulated time until {@code .stopMAS} or {@link #stop()}: whenever
     * every agent is idle, {@code time} jumps to the earliest timer due (or {@code .stopMAS(T)}'s
     * deadline) instead of sleeping. Only for systems whose every event comes from the agents
     * themselves: an environment acting on threads of its own would race simulated time.
     * {@return false when the run ended because nothing could happen any more: every agent
     * idle and no timer due}
     */
    public boolean runSimulated(SimulatedTime time) {
        useClock(time);
        simulatedTime = time;
        while (!stopped) {
            runUntilQuiescent(Long.MAX_VALUE);
            if (stopped) {
                break;
            }
            long due = simulatedStopDue;
            for (Agent a : agentList()) {
                if (!a.isStopped()) {
                    due = Math.min(due, a.nextTimerDue());
                }
            }
            if (due == Long.MAX_VALUE) {
                return false;
            }
            time.advanceTo(due);
            if (simulatedStopDue <= time.millis()) {
                stop();
            }
        }
        return true;
    }

    // ---- threads ----------------------------------------------------------------------------------

    /** An agent created while the system runs: it gets its own thread when agents have threads. */
    String spawn(String name, AgentProgram program, AslParser parser) {
        return start(createUnderFreeName(name, program, parser));
    }

    /** A copy of an agent: its beliefs are there from the start, without {@code +b} events. */
    String spawnCopy(String name, AgentProgram program, AslParser parser) {
        Agent ag = createUnderFreeName(name, program, parser);
        ag.circumstance().eventList().forEach(ag.circumstance()::removeEvent);
        return start(ag);
    }

    /** Creates an agent under {@code name} or, when it is taken, Jason's next free one ({@link #newAgentName}). */
    private synchronized Agent createUnderFreeName(String name, AgentProgram program, AslParser parser) {
        return createAgent(newAgentName(name), program, parser, null);
    }

    private String start(Agent ag) {
        String name = ag.name();
        if (threadsRunning) {
            Thread t = new Thread(() -> agentLoop(ag, null), "agent-" + name);
            t.setDaemon(true);
            t.start();
        }
        wakeStepping();
        return name;
    }

    /** Stops an agent and takes it out of the system. */
    boolean kill(String name) {
        Agent ag;
        synchronized (this) {
            ag = agents.remove(name);
        }
        if (ag == null) {
            return false;
        }
        ag.stop();
        wake(name);
        wakers.remove(name);
        return true;
    }

    /** Runs each agent on its own thread until {@code .stopMAS}. */
    public void runThreads() throws InterruptedException {
        threadsRunning = true;
        var threads = new ArrayList<Thread>();
        // the agents begin once every thread is up: started while the first agents already
        // reasoned, a thousand threads took over a second (the starting thread had a share of
        // the CPU among a thousand), against a tenth of that before any agent runs
        var allStarted = new CountDownLatch(1);
        for (Agent a : agentList()) {
            Thread t = new Thread(() -> agentLoop(a, allStarted), "agent-" + a.name());
            t.setDaemon(true);
            threads.add(t);
        }
        threads.forEach(Thread::start);
        allStarted.countDown();
        finished.await();
        for (Thread t : threads) {
            t.join(2000);
        }
    }

    /**
     * How long an agent receiving a stream of messages lingers when it runs out of work (system
     * property jacabot.lingerMicros; 0 never lingers). An agent whose mailbox held two messages or
     * more when a wake ended its park receives them faster than it wakes: when idle, it parks
     * this long without raising {@code asleep}, so that its senders need not unpark it, and takes
     * what came meanwhile in one go; it lingers again while each linger brings a message. Any
     * other idle agent parks until the next wake, which ends the park at once: an agent in a
     * conversation (one message a wake) answers as soon as before.
     */
    static final long LINGER_NANOS = TimeUnit.MICROSECONDS.toNanos(Long.getLong("jacabot.lingerMicros", 50));

    private void agentLoop(Agent a, CountDownLatch allStarted) {
        Waker w = wakers.get(a.name());
        w.thread = Thread.currentThread();
        try {
            if (allStarted != null) {
                allStarted.await();
            }
            boolean linger = false;
            while (!stopped && !a.isStopped()) {
                if (!a.canSleep()) {
                    a.reasoningCycle();
                    continue;
                }
                if (linger && !w.woken) {
                    LockSupport.parkNanos(this, LINGER_NANOS);
                    if (Thread.interrupted()) {
                        throw new InterruptedException();
                    }
                    linger = a.circumstance().hasMessage();
                    w.woken = false;
                    continue;
                }
                if (w.woken) {
                    // a wake came since the last look: look again, without raising asleep,
                    // which makes every waker unpark this thread
                    w.woken = false;
                    continue;
                }
                w.asleep = true;
                try {
                    if (!w.woken && a.canSleep()) {
                        long due = a.nextTimerDue();
                        // capped: a simulated clock may run faster than the wall clock
                        long wait = due == Long.MAX_VALUE ? 1000 : Math.max(1, Math.min(50, due - clock.millis()));
                        LockSupport.parkNanos(this, TimeUnit.MILLISECONDS.toNanos(wait));
                        if (Thread.interrupted()) {
                            throw new InterruptedException();
                        }
                        linger = LINGER_NANOS > 0 && a.circumstance().messageCount() >= 2;
                    }
                    w.woken = false;
                } finally {
                    w.asleep = false;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            console("[" + a.name() + "] *** internal error: " + e);
            e.printStackTrace();
        }
    }
}
