package jacabot.cartago;

/**
 * An agent's body in a workspace ({@code body_<agent>}): {@code focus(Id)} makes the calling
 * agent observe an artifact (its properties now, then every change and signal) and
 * {@code stopFocus(Id)} ends it. Id is an ArtifactId or an artifact's name.
 */
public class AgentBodyArtifact extends Artifact {
    /** Starts observing an artifact; focusing it again does nothing. */
    @OPERATION
    void focus(Object id) {
        Workspace ws = core().workspace();
        ws.focusBook().focus(getCurrentOpAgentId(), ws.resolve(id));
    }

    /** Stops observing an artifact; fails if the agent was not observing it. */
    @OPERATION
    void stopFocus(Object id) {
        Workspace ws = core().workspace();
        ws.focusBook().stopFocus(getCurrentOpAgentId(), ws.resolve(id));
    }

    /**
     * Focuses the artifact called {@code name} as soon as it exists (checked every 20 ms of the
     * workspace's clock, without holding anything meanwhile).
     */
    @OPERATION
    void focusWhenAvailable(String name) {
        Workspace ws = core().workspace();
        while (ws.lookup(name).isEmpty()) {
            await_time(20);
        }
        ws.focusBook().focus(getCurrentOpAgentId(), ws.resolve(name));
    }
}
