package jacabot.cartago;

/**
 * The {@code workspace} artifact of every workspace: making, finding and disposing artifacts.
 * Operations: {@code makeArtifact(Name, ClassName[, Params[, ?Id]])},
 * {@code lookupArtifact(Name, ?Id)}, {@code disposeArtifact(Id)}, {@code linkArtifacts(Id, Port, Id)}
 * (Id: an ArtifactId or a name).
 */
public class WorkspaceArtifact extends Artifact {
    /** Makes an artifact without init parameters. */
    @OPERATION
    void makeArtifact(String name, String className) {
        make(name, className, new Object[0]);
    }

    /** Makes an artifact, passing {@code params} (a list) to its init. */
    @OPERATION
    void makeArtifact(String name, String className, Object[] params) {
        make(name, className, params);
    }

    /** Makes an artifact and gives back its id. */
    @OPERATION
    void makeArtifact(String name, String className, Object[] params, OpFeedbackParam<ArtifactId> id) {
        id.set(make(name, className, params));
    }

    /** Gives the id of the artifact called {@code name}; fails if there is none. */
    @OPERATION
    void lookupArtifact(String name, OpFeedbackParam<ArtifactId> id) {
        id.set(core().workspace().lookup(name).orElseThrow(() ->
                new OpFailedException("artifact " + name + " not found", "unknown_artifact", name)));
    }

    /** Disposes an artifact made by an agent. */
    @OPERATION
    void disposeArtifact(Object id) {
        core().workspace().disposeFor(id);
    }

    /** Links the out port {@code port} of {@code linking} to {@code linked} (ids or names). */
    @OPERATION
    void linkArtifacts(Object linking, String port, Object linked) {
        Workspace ws = core().workspace();
        ws.resolve(linking).link(port, ws.resolve(linked).id());
    }

    private ArtifactId make(String name, String className, Object[] params) {
        return core().workspace().create(name, className, params, getCurrentOpAgentId());
    }
}
