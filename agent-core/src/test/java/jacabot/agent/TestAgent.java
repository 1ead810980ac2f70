package jacabot.agent;

import static org.junit.jupiter.api.Assertions.fail;

import jacabot.agent.parser.AslParser;
import jacabot.agent.runtime.Clock;
import jacabot.agent.runtime.SimulatedClock;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.AgentArch;
import jacabot.agent.stdlib.Stdlib;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * A test harness in the spirit of Jason's asunit {@code TestAgent}: an agent parsed from inline
 * AgentSpeak, a scripted architecture that records console lines and actions, a simulated clock,
 * and assertions that wait a bounded number of reasoning cycles.
 */
public final class TestAgent implements AgentArch {
    public final List<String> console = new ArrayList<>();
    public final List<ActionExec> actions = new ArrayList<>();
    public final SimulatedClock clock = new SimulatedClock();
    /** Decides each action's outcome; default: success. */
    public Function<ActionExec, Boolean> environment = a -> true;
    public List<Literal> percepts;
    public final Agent agent;
    private boolean stopped;

    public TestAgent(String name, String source) {
        var parser = new AslParser();
        agent = new Agent(name, this, Stdlib.defaults(), 42, parser);
        try {
            agent.load(parser.parse(source, name + ".asl"));
        } catch (Exception e) {
            throw new AssertionError("cannot parse test agent: " + e.getMessage(), e);
        }
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

    @Override
    public void act(ActionExec action, Agent ag) {
        actions.add(action);
        if (environment.apply(action)) {
            action.succeed();
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
        return clock;
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
        clock.advance(ms);
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
        fail("no belief " + formula + " within " + maxCycles + " cycles; printed " + printed());
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
        fail("no action " + action + " within " + maxCycles + " cycles; actions " + actions);
    }

    public List<String> actionNames() {
        var out = new ArrayList<String>();
        for (ActionExec a : actions) {
            out.add(a.action().toString());
        }
        return out;
    }
}
