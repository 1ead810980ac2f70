package jacabot.cartago.bridge;

import jacabot.agent.runtime.Environment;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Clock;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
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
import jacabot.cartago.WorkspaceId;
import java.io.PrintStream;
import java.time.LocalTime;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * JaCa's {@code c4jason.CartagoEnvironment}: agents start in a workspace {@code main}, and every
 * action that is not an internal action is an operation of one of its artifacts. In a
 * {@code .mas2j}: {@code environment: jacabot.cartago.bridge.CartagoEnvironment} (optionally with the
 * argument {@code "stepped"}, or {@code "infrastructure"} to let agents of other processes join this
 * node's workspaces, see {@link RemoteNodes}), and each agent with
 * {@code agentArchClass jacabot.cartago.bridge.CAgentArch}.
 *
 * <p>The node holds several workspaces: {@code createWorkspace}, {@code joinWorkspace},
 * {@code joinRemoteWorkspace} and {@code quitWorkspace} are handled here; other actions go to the
 * workspace of their {@code [artifact_id(Id)]}, to the one named by {@code [wsp(Name)]} or
 * {@code [wsp_id(Id)]}, or else to the agent's current workspace ({@link AgentSession}).
 */
public class CartagoEnvironment implements Environment {
    /** The actions about workspaces themselves, which no artifact runs. */
    private static final Set<String> NODE_ACTIONS = Set.of("createWorkspace", "joinWorkspace",
            "joinRemoteWorkspace", "quitWorkspace");

    private final Map<String, Workspace> workspaces = new LinkedHashMap<>();
    private final Map<String, AgentSession> sessions = new HashMap<>();
    private Workspace workspace;
    private FollowingClock clock;
    private PrintStream console = System.out;
    private ClassLoader loader;
    private RemoteNodes remote;

    /** For {@code .mas2j} files: the workspace is made in {@link #init}. */
    public CartagoEnvironment() {
    }

    /** With a workspace made by the caller (e.g. stepped, with a simulated clock). */
    public CartagoEnvironment(Workspace workspace) {
        this.workspace = workspace;
        workspaces.put(workspace.getName(), workspace);
    }

    @Override
    public void init(LocalMAS mas, List<String> args) {
        ClassLoader context = Thread.currentThread().getContextClassLoader();
        loader = context != null ? context : getClass().getClassLoader();
        console = mas.consoleStream();
        if (workspace == null) {
            // agents and artifacts share one clock, which follows a simulation when an artifact says so
            clock = new FollowingClock();
            FollowingClock c = clock;
            mas.useClock(new Clock() {
                @Override
                public long millis() {
                    return c.nowMillis();
                }

                @Override
                public LocalTime timeOfDay() {
                    return c.isFollowing() ? Clock.super.timeOfDay() : LocalTime.now();
                }
            });
            var b = builder("main");
            if (args.contains("stepped")) {
                b.stepped();
            }
            workspace = b.build();
            workspaces.put("main", workspace);
        }
        remote = new RemoteNodes(this, args, console);
    }

    private Workspace.Builder builder(String name) {
        // the project's own artifact classes (ProjectClasses) come through the launcher's context loader
        return Workspace.builder(name).clock(clock).console(console).logger(CartagoLogger.console(console))
                .classLoader(loader);
    }

    /** {@return the default workspace, {@code main}} */
    public Workspace workspace() {
        return workspace;
    }

    /** {@return the workspace of this node called {@code name}} */
    public synchronized Optional<Workspace> workspace(String name) {
        return Optional.ofNullable(workspaces.get(name));
    }

    /** {@return the class loader of the project's classes (artifacts, Java data binding)} */
    ClassLoader classLoader() {
        return loader;
    }

    /**
     * Makes a workspace on this node (CArtAgO's {@code createWorkspace}).
     *
     * @throws IllegalArgumentException if the name is in use, or workspaces are stepped
     */
    public synchronized Workspace createWorkspace(String name) {
        if (workspaces.containsKey(name)) {
            throw new IllegalArgumentException("workspace " + name + " already exists");
        }
        if (workspace.mode() == Workspace.Mode.STEPPED) {
            throw new IllegalArgumentException("a stepped node makes no more workspaces");
        }
        if (clock == null) {
            throw new IllegalArgumentException("this node's workspace was made by its host, which makes no more");
        }
        Workspace w = builder(name).build();
        workspaces.put(name, w);
        return w;
    }

    /** Joins an agent to {@code main} with the observer through which it perceives every workspace. */
    public AgentId join(String agent, ArtifactObserver observer) {
        return session(agent, observer).find(WorkspaceId.local(workspace.getName()))
                .map(j -> ((JoinedWorkspace.Local) j).agent()).orElseThrow();
    }

    /** The agent's session, made (joining {@code main}) on first use. */
    synchronized AgentSession session(String agent, ArtifactObserver observer) {
        AgentSession s = sessions.get(agent);
        if (s == null) {
            s = new AgentSession(agent, observer);
            sessions.put(agent, s);
            s.joined(new JoinedWorkspace.Local(workspace, workspace.join(agent, observer)));
        }
        return s;
    }

    private AgentSession session(String agent) {
        return session(agent, new ArtifactObserverAdapter());
    }

    /**
     * Runs the action: a workspace action here, any other as an operation, in the workspace its
     * annotations or its artifact id name, else in the agent's current one. Unbound variables are
     * output parameters, bound when the operation succeeds.
     */
    @Override
    public void execute(String agent, ActionExec action, Agent ag) {
        Literal act = action.action();
        AgentSession session = session(agent);
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
        Reply reply = new Reply(action, ag, outputs);
        if (NODE_ACTIONS.contains(act.functor())) {
            new NodeActions(this, session, remote).execute(act.functor(), args, reply);
            return;
        }
        OpTarget target = OpTarget.any();
        ArtifactId artifact = null;
        Literal byId = act.getAnnot("artifact_id");
        Literal byName = act.getAnnot("artifact_name");
        if (byId != null && byId.arity() == 1 && TermConverter.toJava(byId.arg(0)) instanceof ArtifactId id) {
            target = OpTarget.id(id);
            artifact = id;
        } else if (byName != null && byName.arity() >= 1) {
            target = OpTarget.name(String.valueOf(TermConverter.toJava(byName.arg(byName.arity() - 1))));
        }
        if (artifact == null && args.length > 0 && args[0] instanceof ArtifactId first) {
            artifact = first;   // focus(Id), stopFocus(Id), disposeArtifact(Id), linkArtifacts(Id, ...)
        }
        JoinedWorkspace where;
        try {
            where = where(session, act, artifact);
        } catch (NotJoined e) {
            reply.fail(e.getMessage(), "not_joined", List.of(e.workspace));
            return;
        }
        where.execOp(target, act.functor(), args, reply::outcome);
    }

    /** The workspace an action goes to. */
    private static JoinedWorkspace where(AgentSession session, Literal act, ArtifactId artifact) {
        Literal wsp = act.getAnnot("wsp");
        Literal wspId = act.getAnnot("wsp_id") != null ? act.getAnnot("wsp_id") : act.getAnnot("wid");
        if (wspId != null && wspId.arity() == 1 && TermConverter.toJava(wspId.arg(0)) instanceof WorkspaceId id) {
            return session.find(id).orElseThrow(() -> notJoined(id.getFullName()));
        }
        if (wsp != null && wsp.arity() == 1) {
            String name = String.valueOf(TermConverter.toJava(wsp.arg(0)));
            return session.byName(name).orElseThrow(() -> notJoined(name));
        }
        if (artifact != null) {
            ArtifactId a = artifact;
            Optional<JoinedWorkspace> holding = session.holding(a);
            if (holding.isPresent()) {
                return holding.get();
            }
            if (!"focus".equals(act.functor()) || session.current().isEmpty()) {
                throw notJoined(a.workspace());
            }
        }
        return session.current().orElseThrow(() -> new NotJoined("", "the agent has quit every workspace"));
    }

    private static NotJoined notJoined(String workspaceName) {
        return new NotJoined(workspaceName, "the agent has not joined workspace " + workspaceName);
    }

    /** An action for a workspace the agent is not in. */
    private static final class NotJoined extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final String workspace;

        NotJoined(String workspace, String message) {
            super(message, null, false, false);
            this.workspace = workspace;
        }
    }

    /** The outcome of one action: binds outputs, or fails with CArtAgO's annotations. */
    static final class Reply {
        private final ActionExec action;
        private final Agent ag;
        private final Map<Integer, Var> outputs;

        Reply(ActionExec action, Agent ag, Map<Integer, Var> outputs) {
            this.action = action;
            this.ag = ag;
            this.outputs = outputs;
        }

        Agent agent() {
            return ag;
        }

        void outcome(OpOutcome outcome) {
            if (outcome instanceof OpOutcome.Success s) {
                succeed(s.outputs());
            } else {
                var f = (OpOutcome.Failure) outcome;
                fail(f.message(), f.reasonFunctor(), f.reasonArgs());
            }
        }

        void succeed(Map<Integer, Object> values) {
            var bindings = ag.newUnifier();
            values.forEach((i, value) -> {
                Var v = outputs.get(i);
                if (v != null) {
                    bindings.bind(v, TermConverter.toTerm(value));
                }
            });
            action.succeed(bindings);
            ag.actionExecuted(action);
        }

        /** Fails with {@code env_failure_reason(functor(args...))} (no reason when functor is null). */
        void fail(String message, String functor, List<Object> args) {
            List<Term> reason = new ArrayList<>();
            if (functor != null) {
                var terms = new ArrayList<Term>();
                args.forEach(v -> terms.add(TermConverter.toTerm(v)));
                reason.add(Literal.of("env_failure_reason", Literal.of(functor, terms)));
            }
            action.fail(message, reason);
            ag.actionExecuted(action);
        }
    }

    static Term nameTerm(WorkspaceId id) {
        return new StringTerm(id.name());
    }

    @Override
    public void stop() {
        if (remote != null) {
            remote.close();
        }
        List<Workspace> all;
        synchronized (this) {
            all = new ArrayList<>(workspaces.values());
        }
        all.forEach(Workspace::close);
    }
}
