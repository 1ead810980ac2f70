package jacabot.cartago.bridge;

import jacabot.cartago.Workspace;
import jacabot.cartago.WorkspaceId;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * CArtAgO's actions on workspaces themselves (its {@code NodeArtifact} and agent session):
 * {@code createWorkspace(Name)}, {@code joinWorkspace(Name[, ?WspId])},
 * {@code joinRemoteWorkspace(Name, Address[, Protocol], ?WspId)} and {@code quitWorkspace[(WspId)]}.
 * Joining makes the workspace the agent's current one; quitting the current one makes the one
 * joined before it current again.
 */
final class NodeActions {
    private final CartagoEnvironment node;
    private final AgentSession session;
    private final RemoteNodes remote;

    NodeActions(CartagoEnvironment node, AgentSession session, RemoteNodes remote) {
        this.node = node;
        this.session = session;
        this.remote = remote;
    }

    void execute(String action, Object[] args, CartagoEnvironment.Reply reply) {
        switch (action) {
            case "createWorkspace" -> create(args, reply);
            case "joinWorkspace" -> join(args, reply);
            case "joinRemoteWorkspace" -> joinRemote(args, reply);
            default -> quit(args, reply);
        }
    }

    private void create(Object[] args, CartagoEnvironment.Reply reply) {
        if (args.length != 1 || !(args[0] instanceof String name)) {
            reply.fail("createWorkspace(Name) takes a workspace name", "wrong_arity", List.of("createWorkspace", args.length));
            return;
        }
        try {
            node.createWorkspace(simpleName(name));
            reply.succeed(Map.of());
        } catch (IllegalArgumentException e) {
            reply.fail(e.getMessage(), "workspace_exists", List.of(name));
        }
    }

    private void join(Object[] args, CartagoEnvironment.Reply reply) {
        if (args.length < 1 || args.length > 2 || !(args[0] instanceof String name)) {
            reply.fail("joinWorkspace(Name[, ?WspId]) takes a workspace name", "wrong_arity", List.of("joinWorkspace", args.length));
            return;
        }
        Optional<Workspace> w = node.workspace(simpleName(name));
        if (w.isEmpty()) {
            reply.fail("no workspace " + name + " on this node", "unknown_workspace", List.of(name));
            return;
        }
        WorkspaceId id = WorkspaceId.local(w.get().getName());
        if (!session.makeCurrent(id)) {
            try {
                session.joined(new JoinedWorkspace.Local(w.get(), w.get().join(session.agent(), session.observer())));
            } catch (IllegalArgumentException e) {
                reply.fail(e.getMessage(), "join_failed", List.of(name));
                return;
            }
        }
        reply.succeed(args.length == 2 ? Map.of(1, id) : Map.of());
    }

    private void joinRemote(Object[] args, CartagoEnvironment.Reply reply) {
        if (args.length < 3 || args.length > 4 || !(args[0] instanceof String name) || !(args[1] instanceof String address)) {
            reply.fail("joinRemoteWorkspace(Name, Address[, Protocol], ?WspId) takes a name and an address",
                    "wrong_arity", List.of("joinRemoteWorkspace", args.length));
            return;
        }
        String protocol = args.length == 4 ? String.valueOf(args[2]) : RemoteNodes.PROTOCOL;
        remote.join(session, simpleName(name), address, protocol, args.length - 1, reply);
    }

    private void quit(Object[] args, CartagoEnvironment.Reply reply) {
        Optional<JoinedWorkspace> w;
        if (args.length == 0) {
            w = session.current();
        } else if (args.length == 1 && args[0] instanceof WorkspaceId id) {
            w = session.find(id);
        } else if (args.length == 1 && args[0] instanceof String name) {
            w = session.byName(name);
        } else {
            reply.fail("quitWorkspace[(WspId)]", "wrong_arity", List.of("quitWorkspace", args.length));
            return;
        }
        if (w.isEmpty()) {
            reply.fail("the agent is in no such workspace", "not_joined", List.of(args.length == 0 ? "" : args[0]));
            return;
        }
        w.get().quit();
        session.quitted(w.get());
        reply.succeed(Map.of());
    }

    /** CArtAgO names workspaces by path ({@code /main/w0}); here they are flat. */
    private static String simpleName(String name) {
        int slash = name.lastIndexOf('/');
        return slash >= 0 ? name.substring(slash + 1) : name;
    }
}
