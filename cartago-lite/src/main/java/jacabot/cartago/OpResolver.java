package jacabot.cartago;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Turns a call {@code operation(args...)} into an {@link OpExecution}: finds the artifact (given,
 * or resolved by name and arity as JaCa does), the method and the converted arguments. Every
 * problem is an {@link OpFailedException} naming what was asked.
 */
final class OpResolver {
    private OpResolver() {
    }

    static OpExecution prepare(Workspace ws, AgentId agent, OpTarget target, String operation, Object[] args,
            OpCallback callback) {
        if (!ws.hasJoined(agent)) {
            throw new OpFailedException("agent " + agent + " has not joined workspace " + ws.getName(),
                    "unknown_agent", agent.name());
        }
        if (target.isAny()) {
            OpExecution first = firstOffering(ws, agent, operation, args, callback);
            if (first != null) {
                return first;
            }
        } else {
            ArtifactCore core = ws.resolve(target.id() != null ? target.id() : target.name());
            OpExecution found = offeredBy(core, operation, args, agent, callback);
            if (found != null) {
                return found;
            }
        }
        // no artifact has it: the message names every candidate's operations of that name
        List<ArtifactCore> candidates = target.isAny() ? candidates(ws, agent)
                : List.of(ws.resolve(target.id() != null ? target.id() : target.name()));
        String signature = operation + "/" + args.length;
        List<String> others = new ArrayList<>();
        for (ArtifactCore core : candidates) {
            for (OpMethod m : core.type().operations(operation, OpMethod.Kind.OPERATION)) {
                others.add(core.id().name() + " has " + m.signature());
            }
        }
        String where = target.isAny() ? "no artifact in workspace " + ws.getName() + " has"
                : "artifact " + candidates.get(0).id().name() + " has no";
        if (!others.isEmpty()) {
            throw new OpFailedException(where + " operation " + signature + " (" + String.join(", ", others) + ")",
                    "wrong_arity", operation, args.length);
        }
        throw new OpFailedException(where + " operation " + signature, "unknown_operation", operation, args.length);
    }

    /**
     * The operation on the first of the agent's {@link #candidates} that has it, or null; looked
     * for in the same order without building the ordered set, since an agent's every operation
     * comes here (a core met twice had no such operation the first time, and has none the second).
     * The artifact found is kept ({@link OpRoutes}) until the artifacts or the focus lists change:
     * the first that has a method of that name and arity is the one, whatever the arguments.
     */
    private static OpExecution firstOffering(Workspace ws, AgentId agent, String operation, Object[] args, OpCallback callback) {
        long focus = ws.focusBook().changes(); // before the lists are read: see FocusBook.changes
        List<ArtifactCore> live = ws.cores();
        ArtifactCore known = ws.routes().get(live, focus, agent, operation, args.length);
        if (known != null) {
            return offeredBy(known, operation, args, agent, callback);
        }
        OpExecution found = firstOffering(ws, live, agent, operation, args, callback);
        if (found != null) {
            ws.routes().put(live, focus, agent, operation, args.length, found.core());
        }
        return found;
    }

    private static OpExecution firstOffering(Workspace ws, List<ArtifactCore> live, AgentId agent, String operation,
            Object[] args, OpCallback callback) {
        for (ArtifactCore core : live) {
            if (agent.equals(core.id().creator())) {
                OpExecution found = offeredBy(core, operation, args, agent, callback);
                if (found != null) {
                    return found;
                }
            }
        }
        for (ArtifactId focused : ws.focusedBy(agent)) {
            for (ArtifactCore core : live) {
                if (core.id().equals(focused)) {
                    OpExecution found = offeredBy(core, operation, args, agent, callback);
                    if (found != null) {
                        return found;
                    }
                }
            }
        }
        for (ArtifactCore core : live) {
            if (!(core.artifact() instanceof AgentBodyArtifact)) {
                OpExecution found = offeredBy(core, operation, args, agent, callback);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    /** {@return the operation bound on {@code core}, or null when it has no operation of that name and arity} */
    private static OpExecution offeredBy(ArtifactCore core, String operation, Object[] args, AgentId agent, OpCallback callback) {
        List<OpMethod> methods = matching(core, operation, args.length, OpMethod.Kind.OPERATION);
        return methods.isEmpty() ? null : bind(core, methods, args, agent, callback);
    }

    /**
     * Prepares an operation one artifact starts: an internal one on itself (internal operations
     * preferred, then ordinary ones) or a linked one on another ({@link LINK} ones preferred).
     */
    static OpExecution prepareFromArtifact(ArtifactCore core, AgentId agent, String operation, Object[] args,
            OpMethod.Kind preferred, OpCallback callback) {
        List<OpMethod> methods = matching(core, operation, args.length, preferred, OpMethod.Kind.OPERATION);
        if (methods.isEmpty()) {
            String kind = preferred == OpMethod.Kind.LINK ? "linked" : "internal";
            throw new OpFailedException("artifact " + core.id().name() + " has no " + kind + " operation " + operation
                    + "/" + args.length, "unknown_operation", operation, args.length);
        }
        return bind(core, methods, args, agent, callback);
    }

    /**
     * The agent's candidates, in JaCa's preference order: created by it, then focused by it, then
     * the rest; other agents' bodies never.
     */
    private static List<ArtifactCore> candidates(Workspace ws, AgentId agent) {
        List<ArtifactCore> live = ws.cores();
        Set<ArtifactCore> ordered = new LinkedHashSet<>();
        for (ArtifactCore core : live) {
            if (agent.equals(core.id().creator())) {
                ordered.add(core);
            }
        }
        for (ArtifactId focused : ws.focusedBy(agent)) {
            for (ArtifactCore core : live) {
                if (core.id().equals(focused)) {
                    ordered.add(core);
                }
            }
        }
        for (ArtifactCore core : live) {
            if (!(core.artifact() instanceof AgentBodyArtifact)) {
                ordered.add(core);
            }
        }
        return new ArrayList<>(ordered);
    }

    /**
     * The methods of that name that accept {@code count} arguments, of the given kinds in that
     * order. No list is made for none or one: every operation asks several artifacts, most of
     * which have none of that name, and the one that has it nearly always has one method for it.
     */
    private static List<OpMethod> matching(ArtifactCore core, String operation, int count, OpMethod.Kind... kinds) {
        OpMethod one = null;
        List<OpMethod> more = null;
        for (OpMethod.Kind kind : kinds) {
            for (OpMethod m : core.type().named(operation)) {
                if (m.kind() != kind || !m.accepts(count)) {
                    continue;
                }
                if (one == null) {
                    one = m;
                } else {
                    if (more == null) {
                        more = new ArrayList<>(List.of(one));
                    }
                    more.add(m);
                }
            }
        }
        return more != null ? more : one != null ? List.of(one) : List.of();
    }

    /** Uses the first method whose parameters accept the arguments (exact arity before varargs). */
    private static OpExecution bind(ArtifactCore core, List<OpMethod> methods, Object[] args, AgentId agent,
            OpCallback callback) {
        List<OpMethod> ordered = methods;
        if (methods.size() > 1) { // nearly always one: nothing to order
            ordered = new ArrayList<>(methods);
            ordered.sort(Comparator.comparing(m -> m.method().isVarArgs())); // stable: keeps kind preference
        }
        ArgConverter.Mismatch first = null;
        for (OpMethod m : ordered) {
            try {
                return new OpExecution(core, m, ArgConverter.convertAll(m.method(), args), agent, callback);
            } catch (ArgConverter.Mismatch e) {
                first = first == null ? e : first;
            }
        }
        throw new OpFailedException(core.id().name() + "." + ordered.get(0).name() + ": " + first.getMessage(),
                "bad_argument", first.index + 1);
    }
}
