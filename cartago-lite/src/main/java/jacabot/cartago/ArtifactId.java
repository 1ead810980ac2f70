package jacabot.cartago;

import java.util.Objects;

/**
 * The identity of an artifact: a number unique in its workspace, its name, its class and the agent
 * that created it ({@code null} for the workspace's own artifacts).
 *
 * @param id the number, unique in the workspace and never reused
 * @param name the name, unique among the workspace's live artifacts
 * @param type the artifact's class name
 * @param workspace the workspace's name
 * @param creator the creating agent, or null
 */
public record ArtifactId(int id, String name, String type, String workspace, AgentId creator) {
    public ArtifactId {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(workspace, "workspace");
    }

    /** {@return the artifact's name; CArtAgO's spelling} */
    public String getName() {
        return name;
    }

    /** {@return the artifact's number; CArtAgO's spelling} */
    public int getId() {
        return id;
    }

    /** {@return the artifact's class name; CArtAgO's spelling} */
    public String getArtifactType() {
        return type;
    }

    /** {@return the creating agent, or null; CArtAgO's spelling} */
    public AgentId getCreatorId() {
        return creator;
    }

    // written out, with the values the record's generated methods give (so hashed collections
    // keep their order): every percept update looks its artifact up by id, and the generated
    // methods go through method handles that stay slow until compiled
    @Override
    public boolean equals(Object o) {
        return o == this || o instanceof ArtifactId a && id == a.id && name.equals(a.name) && type.equals(a.type)
                && workspace.equals(a.workspace) && Objects.equals(creator, a.creator);
    }

    @Override
    public int hashCode() {
        return (((Integer.hashCode(id) * 31 + name.hashCode()) * 31 + type.hashCode()) * 31 + workspace.hashCode()) * 31
                + Objects.hashCode(creator);
    }

    /** Prints as JaCa prints artifact ids. */
    @Override
    public String toString() {
        return "cobj_" + id;
    }
}
