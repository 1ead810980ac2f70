package jacabot.agent.testing;

import jacabot.agent.parser.AslParser;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.AgentArch;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.Clock;
import jacabot.agent.semantics.Message;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/**
 * The architecture of a tester agent under {@code jacabot test}: its environment actions (a robot
 * skill's artifact operations) are answered by the agent's own mock beliefs, so that a skill's
 * plans are tested without a robot, a world or an artifact.
 *
 * <pre>
 * mock_operation(Pattern, Outcome)   Outcome: ok | fail | fail(Msg) | fail(Msg, Reason)
 * </pre>
 *
 * The first belief (in belief-base order) whose pattern unifies with the action decides: {@code ok}
 * succeeds and binds the action's free variables to the pattern's values (an operation's output
 * parameters: {@code mock_operation(lookupArtifact(_, mw), ok)} binds the id to {@code mw});
 * {@code fail...} fails it as a failed artifact operation does ({@code error(action_failed)},
 * {@code error_msg(Msg)}, {@code env_failure_reason(Reason)}). Every action performed is then
 * believed as {@code mock_called(Action)} (with its outputs bound). {@code println} and
 * {@code print} without a mock print as the console artifact does. Any other action without a
 * mock fails with {@code env_failure_reason(not_mocked)}.
 */
public final class MockingArch implements AgentArch {
    static final String MOCK = "mock_operation";
    static final String CALLED = "mock_called";
    private final AgentArch inner;

    public MockingArch(AgentArch inner) {
        this.inner = inner;
    }

    @Override
    public void act(ActionExec action, Agent agent) {
        Literal act = action.action().withoutAnnots();
        Unifier u = new Unifier();
        Term outcome = find(agent.beliefBase(), act, u);
        if (outcome == null) {
            if (act.functor().equals("println") || act.functor().equals("print")) {
                agent.print(consoleText(act.args()));
                agent.runAtBeginOfNextCycle(() -> agent.addBelief(called(act), true));
                action.succeed();
            } else {
                action.fail("operation " + act + " is not mocked: add a belief mock_operation(" + act + ", ok) (or fail)",
                        List.of(Literal.of("env_failure_reason", Literal.atom("not_mocked"))));
            }
        } else if (outcome instanceof Literal o && o.functor().equals("fail") && o.arity() <= 2) {
            String message = o.arity() >= 1 ? text(o.arg(0)) : "mocked failure of " + act;
            Term reason = o.arity() == 2 ? o.arg(1) : Literal.atom("mocked");
            agent.runAtBeginOfNextCycle(() -> agent.addBelief(called(act), true));
            action.fail(message, List.of(Literal.of("env_failure_reason", reason)));
        } else {
            Unifier outputs = agent.newUnifier();
            collectVars(act, u, outputs);
            Literal done = (Literal) u.apply(act);
            agent.runAtBeginOfNextCycle(() -> agent.addBelief(called(done), true));
            action.succeed(outputs);
        }
        agent.actionExecuted(action);
    }

    /** The outcome of the first mock belief whose pattern unifies with {@code act} (bindings into u), or null. */
    private static Term find(BeliefBase bb, Literal act, Unifier u) {
        Literal probe = Literal.of(MOCK, new Var("P"), new Var("O"));
        for (BeliefBase.Entry e : bb.candidates(probe)) {
            Literal b = e.literal();
            if (e.rule() != null || !b.functor().equals(MOCK) || b.arity() != 2) {
                continue;
            }
            Unifier trial = new Unifier();
            Term pattern = b.arg(0) instanceof Literal l ? l.withoutAnnots() : b.arg(0);
            if (trial.unifies(pattern, act)) {
                u.setFrom(trial);
                return u.apply(b.arg(1));
            }
        }
        return null;
    }

    /** The bindings of the action's own free variables (its output parameters). */
    private static void collectVars(Term t, Unifier u, Unifier into) {
        t.collectVars(v -> {
            Term value = u.apply(v);
            if (!(value instanceof Var)) {
                into.bind(v, value);
            }
        });
    }

    private static Literal called(Literal act) {
        return Literal.of(CALLED, act).addAnnot(Literal.SOURCE_SELF);
    }

    private static String text(Term t) {
        return t instanceof StringTerm s ? s.value() : t.toString();
    }

    /** As the console artifact prints: strings unquoted, integral numbers without ".0". */
    static String consoleText(List<Term> args) {
        var sb = new StringBuilder();
        for (Term a : args) {
            if (a instanceof NumberTerm n && n.value() == Math.rint(n.value()) && !Double.isInfinite(n.value())) {
                sb.append((long) n.value());
            } else {
                sb.append(text(a));
            }
        }
        return sb.toString();
    }

    // ---- everything else is the wrapped architecture's ------------------------------------------

    @Override
    public void sense(Agent agent) {
        inner.sense(agent);
    }

    @Override
    public boolean canSleep() {
        return inner.canSleep();
    }

    @Override
    public List<Literal> perceive() {
        return inner.perceive();
    }

    @Override
    public boolean sendMessage(Message m) {
        return inner.sendMessage(m);
    }

    @Override
    public List<String> agentNames() {
        return inner.agentNames();
    }

    @Override
    public void console(String line) {
        inner.console(line);
    }

    @Override
    public void stopMAS() {
        inner.stopMAS();
    }

    @Override
    public void stopMAS(long deadlineMs) {
        inner.stopMAS(deadlineMs);
    }

    @Override
    public Clock clock() {
        return inner.clock();
    }

    @Override
    public void wake() {
        inner.wake();
    }

    @Override
    public boolean dfRegister(String agent, String service) {
        return inner.dfRegister(agent, service);
    }

    @Override
    public boolean dfDeregister(String agent, String service) {
        return inner.dfDeregister(agent, service);
    }

    @Override
    public Collection<String> dfSearch(String service) {
        return inner.dfSearch(service);
    }

    @Override
    public boolean dfSubscribe(String agent, String service) {
        return inner.dfSubscribe(agent, service);
    }

    @Override
    public String createAgent(String agentName, AgentProgram program, AslParser parser) {
        return inner.createAgent(agentName, program, parser);
    }

    @Override
    public String cloneAgent(String agentName, AgentProgram program, AslParser parser) {
        return inner.cloneAgent(agentName, program, parser);
    }

    @Override
    public boolean killAgent(String agentName) {
        return inner.killAgent(agentName);
    }
}
