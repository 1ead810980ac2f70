package jacabot.cartago.bridge;

import jacabot.agent.runtime.Environment;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserver;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.FollowingClock;
import jacabot.cartago.OpFeedbackParam;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.OpTarget;
import jacabot.cartago.Workspace;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * JaCa's {@code c4jason.CartagoEnvironment}: agents work in a workspace {@code main}, and every
 * action that is not an internal action is an operation of one of its artifacts. In a
 * {@code .mas2j}: {@code environment: jacabot.cartago.bridge.CartagoEnvironment} (optionally with the
 * argument {@code "stepped"}), and each agent with {@code agentArchClass jacabot.cartago.bridge.CAgentArch}.
 */
public class CartagoEnvironment implements Environment {
    private Workspace workspace;
    private final Map<String, AgentId> agents = new HashMap<>();

    /** For {@code .mas2j} files: the workspace is made in {@link #init}. */
    public CartagoEnvironment() {
    }

    /** With a workspace made by the caller (e.g. stepped, with a simulated clock). */
    public CartagoEnvironment(Workspace workspace) {
        this.workspace = workspace;
    }

    @Override
    public void init(LocalMAS mas, List<String> args) {
        if (workspace == null) {
            // agents and artifacts share one clock, which follows a simulation when an artifact says so
            var clock = new FollowingClock();
            mas.useClock(new jacabot.agent.semantics.Clock() {
                @Override
                public long millis() {
                    return clock.nowMillis();
                }

                @Override
                public java.time.LocalTime timeOfDay() {
                    return clock.isFollowing() ? jacabot.agent.semantics.Clock.super.timeOfDay() : java.time.LocalTime.now();
                }
            });
            var b = Workspace.builder("main").clock(clock).console(mas.consoleStream())
                    .logger(CartagoLogger.console(mas.consoleStream()));
            // the project's own artifact classes (ProjectClasses) come through the launcher's context loader
            ClassLoader loader = Thread.currentThread().getContextClassLoader();
            if (loader != null) {
                b.classLoader(loader);
            }
            if (args.contains("stepped")) {
                b.stepped();
            }
            workspace = b.build();
        }
    }

    public Workspace workspace() {
        return workspace;
    }

    /** Joins an agent with the observer through which it perceives. */
    public synchronized AgentId join(String agent, ArtifactObserver observer) {
        AgentId id = workspace.join(agent, observer);
        agents.put(agent, id);
        return id;
    }

    private synchronized AgentId agentId(String agent) {
        return agents.computeIfAbsent(agent, a -> workspace.join(a, new ArtifactObserverAdapter()));
    }

    /**
     * Runs the action as an operation. An {@code [artifact_id(Id)]} or {@code [artifact_name(N)]}
     * annotation names the artifact; otherwise it is found by name and arity. Unbound variables
     * are output parameters, bound when the operation succeeds.
     */
    @Override
    public void execute(String agent, ActionExec action, Agent ag) {
        Literal act = action.action();
        OpTarget target = OpTarget.any();
        Literal byId = act.getAnnot("artifact_id");
        Literal byName = act.getAnnot("artifact_name");
        if (byId != null && byId.arity() == 1 && TermConverter.toJava(byId.arg(0)) instanceof ArtifactId id) {
            target = OpTarget.id(id);
        } else if (byName != null && byName.arity() >= 1) {
            target = OpTarget.name(String.valueOf(TermConverter.toJava(byName.arg(byName.arity() - 1))));
        }
        Object[] args = new Object[act.arity()];
        Map<Integer, Var> outputs = new HashMap<>();
        for (int i = 0; i < args.length; i++) {
            Term t = act.arg(i);
            if (t instanceof Var v) {
                args[i] = new OpFeedbackParam<Object>();
                outputs.put(i, v);
            } else {
                args[i] = TermConverter.toJava(t);
            }
        }
        workspace.execOp(agentId(agent), target, act.functor(), args, outcome -> {
            if (outcome instanceof OpOutcome.Success s) {
                var bindings = ag.newUnifier();
                s.outputs().forEach((i, value) -> {
                    Var v = outputs.get(i);
                    if (v != null) {
                        bindings.bind(v, TermConverter.toTerm(value));
                    }
                });
                action.succeed(bindings);
            } else {
                var f = (OpOutcome.Failure) outcome;
                List<Term> reason = new ArrayList<>();
                if (f.reasonFunctor() != null) {
                    reason.add(Literal.of("env_failure_reason",
                            Literal.of(f.reasonFunctor(), new ArrayList<>(toTerms(f.reasonArgs())))));
                }
                action.fail(f.message(), reason);
            }
            ag.actionExecuted(action);
        });
    }

    private static List<Term> toTerms(List<Object> values) {
        var out = new ArrayList<Term>();
        values.forEach(v -> out.add(TermConverter.toTerm(v)));
        return out;
    }

    @Override
    public void stop() {
        workspace.close();
    }
}
