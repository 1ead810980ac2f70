package jacabot.agent.testing;



import jacabot.agent.parser.AslParser;
import jacabot.agent.semantics.Clock;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.AgentArch;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.stdlib.Stdlib;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BiConsumer;
import java.util.function.Function;

/**
 * A test harness in the spirit of Jason's asunit {@code TestAgent}: an agent parsed from inline
 * AgentSpeak, a scripted architecture that records console lines and actions, a simulated clock,
 * and assertions that wait a bounded number of reasoning cycles. Shipped in the main code (as
 * Jason ships asunit) so that other modules' tests can script an agent's world.
 */
public final class TestAgent implements AgentArch {
    public final List<String> console = new ArrayList<>();
    public final List<ActionExec> actions = new ArrayList<>();
    /** Simulated time in ms; only {@link #advance} moves it. */
    private final AtomicLong now = new AtomicLong();
    /** Decides each action's outcome; default: success. */
    public Function<ActionExec, Boolean> environment = a -> true;
    public List<Literal> percepts;
    public final Agent agent;
    private boolean stopped;

    /** Binds output variables of a successful action (e.g. the id of {@code makeArtifact}). */
    public BiConsumer<ActionExec, Unifier> outputs = (a, u) -> {
    };

    public TestAgent(String name, String source) {
        var parser = new AslParser();
        agent = new Agent(name, this, Stdlib.defaults(), 42, parser);
        try {
            agent.load(parser.parse(source, name + ".asl"));
        } catch (Exception e) {
            throw new AssertionError("cannot parse test agent: " + e.getMessage(), e);
        }
    }

    private TestAgent(String name, Path file) {
        var parser = new AslParser(List.of(file.toAbsolutePath().getParent()));
        agent = new Agent(name, this, Stdlib.defaults(), 42, parser);
        try {
            agent.load(parser.parseFile(file));
        } catch (Exception e) {
            throw new AssertionError("cannot parse " + file + ": " + e.getMessage(), e);
        }
    }

    /** An agent read from a source file. */
    public static TestAgent fromFile(String name, Path file) {
        return new TestAgent(name, file);
    }

    private Term term(String text) {
        try {
            return agent.parser().parseTerm(text);
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }

    /** Adds a belief as an artifact's observable property would ({@code source(percept)}). */
    public TestAgent percept(String literal) {
        agent.addPercept(((Literal) term(literal)).addAnnot(Literal.SOURCE_PERCEPT));
        return this;
    }

    /** Removes a belief added by {@link #percept}. */
    public TestAgent unpercept(String literal) {
        agent.removePercept(((Literal) term(literal)).addAnnot(Literal.SOURCE_PERCEPT));
        return this;
    }

    /** Posts a non-persistent {@code +s} event, as an artifact's signal. */
    public TestAgent signal(String literal) {
        agent.addExternalEvent(new Trigger(Trigger.Op.ADD,
                Trigger.Type.BELIEF, ((Literal) term(literal)).addAnnot(Literal.SOURCE_PERCEPT)));
        return this;
    }

    public TestAgent(String source) {
        this("bob", source);
    }

    @Override
    public List<Literal> perceive() {
        List<Literal> p = percepts;
        percepts = null;
        return p;
    }

    /** When set, actions stay in progress until {@link #finishActions()}, as in a slow environment. */
    public boolean deferFeedback;
    private final List<ActionExec> inProgress = new ArrayList<>();

    @Override
    public void act(ActionExec action, Agent ag) {
        actions.add(action);
        if (deferFeedback) {
            inProgress.add(action);
            return;
        }
        finish(action, ag);
    }

    /** Ends the actions held by {@link #deferFeedback}, in the order they started. */
    public TestAgent finishActions() {
        List<ActionExec> done = List.copyOf(inProgress);
        inProgress.clear();
        done.forEach(a -> finish(a, agent));
        return this;
    }

    private void finish(ActionExec action, Agent ag) {
        if (environment.apply(action)) {
            var u = new Unifier();
            outputs.accept(action, u);
            action.succeed(u);
        } else {
            action.fail("scripted failure", List.of());
        }
        ag.actionExecuted(action);
    }

    @Override
    public boolean canSleep() {
        return percepts == null;
    }

    @Override
    public void console(String line) {
        console.add(line);
    }

    @Override
    public void stopMAS() {
        stopped = true;
    }

    @Override
    public Clock clock() {
        return now::get;
    }

    public boolean isStopped() {
        return stopped;
    }

    /** Runs cycles while the agent has something to do, at most {@code max}. */
    public TestAgent cycles(int max) {
        for (int i = 0; i < max && !agent.isStopped() && !agent.canSleep(); i++) {
            agent.reasoningCycle();
        }
        return this;
    }

    /** Advances simulated time, then runs the cycles that become possible. */
    public TestAgent advance(long ms, int maxCycles) {
        now.addAndGet(Math.max(0, ms));
        return cycles(maxCycles);
    }

    /** {@return the console lines without the {@code [name] } prefix} */
    public List<String> printed() {
        var out = new ArrayList<String>();
        String prefix = "[" + agent.name() + "] ";
        for (String l : console) {
            out.add(l.startsWith(prefix) ? l.substring(prefix.length()) : l);
        }
        return out;
    }

    public boolean believes(String formula) {
        try {
            Term t = agent.parser().parseTerm(formula);
            return agent.solver().believes(t, agent.newUnifier());
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }

    public void assertBel(String formula, int maxCycles) {
        for (int i = 0; i <= maxCycles; i++) {
            if (believes(formula)) {
                return;
            }
            if (agent.isStopped() || agent.canSleep()) {
                break;
            }
            agent.reasoningCycle();
        }
        throw new AssertionError("no belief " + formula + " within " + maxCycles + " cycles; printed " + printed());
    }

    public void assertAct(String action, int maxCycles) {
        for (int i = 0; i <= maxCycles; i++) {
            for (ActionExec a : actions) {
                if (a.action().toString().equals(action)) {
                    return;
                }
            }
            if (agent.isStopped() || agent.canSleep()) {
                break;
            }
            agent.reasoningCycle();
        }
        throw new AssertionError("no action " + action + " within " + maxCycles + " cycles; actions " + actions);
    }

    public List<String> actionNames() {
        var out = new ArrayList<String>();
        for (ActionExec a : actions) {
            out.add(a.action().toString());
        }
        return out;
    }
}
