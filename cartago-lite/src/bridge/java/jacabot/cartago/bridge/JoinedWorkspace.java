package jacabot.cartago.bridge;

import jacabot.cartago.AgentId;
import jacabot.cartago.OpCallback;
import jacabot.cartago.OpTarget;
import jacabot.cartago.Workspace;
import jacabot.cartago.WorkspaceId;
import jacabot.cartago.remote.RemoteWorkspace;

/** An agent's presence in one workspace, of this process or remote: where its actions go. */
interface JoinedWorkspace {
    WorkspaceId id();

    /** Runs an operation as the agent; the callback is told the outcome exactly once. */
    void execOp(OpTarget target, String operation, Object[] args, OpCallback callback);

    /** Leaves the workspace: focus ends, the body goes. */
    void quit();

    /** A workspace of this process. */
    record Local(Workspace workspace, AgentId agent) implements JoinedWorkspace {
        @Override
        public WorkspaceId id() {
            return WorkspaceId.local(workspace.getName());
        }

        @Override
        public void execOp(OpTarget target, String operation, Object[] args, OpCallback callback) {
            workspace.execOp(agent, target, operation, args, callback);
        }

        @Override
        public void quit() {
            workspace.leave(agent);
        }
    }

    /** A workspace of another process, through a session of its node. */
    record Remote(RemoteWorkspace session, WorkspaceId id) implements JoinedWorkspace {
        @Override
        public void execOp(OpTarget target, String operation, Object[] args, OpCallback callback) {
            session.execOp(target, operation, args, callback);
        }

        @Override
        public void quit() {
            session.quit();
        }
    }
}
