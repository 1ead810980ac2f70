package jacabot.cartago.bridge;

import java.util.List;

/** Placeholder: remote workspaces. */
final class RemoteNodes {
    static final String PROTOCOL = "jacabot";

    RemoteNodes(CartagoEnvironment env, List<String> args) {
    }

    void join(AgentSession session, String name, String address, String protocol, int outputIndex,
            CartagoEnvironment.Reply reply) {
        reply.fail("no remote workspaces yet", "not_supported", List.of("joinRemoteWorkspace"));
    }

    void close() {
    }
}
