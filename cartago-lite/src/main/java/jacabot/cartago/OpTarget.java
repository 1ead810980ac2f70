package jacabot.cartago;

import java.util.Objects;

/**
 * Which artifact an operation call is for: a given id, a given name, or any artifact that has the
 * operation (JaCa's resolution by name and arity, see {@link Workspace}).
 */
public final class OpTarget {
    private static final OpTarget ANY = new OpTarget(null, null);

    private final ArtifactId id;
    private final String name;

    private OpTarget(ArtifactId id, String name) {
        this.id = id;
        this.name = name;
    }

    /** {@return the target that lets the workspace resolve the artifact by operation name and arity} */
    public static OpTarget any() {
        return ANY;
    }

    /** {@return the target naming the artifact by id} */
    public static OpTarget id(ArtifactId id) {
        return new OpTarget(Objects.requireNonNull(id, "id"), null);
    }

    /** {@return the target naming the artifact by name} */
    public static OpTarget name(String name) {
        return new OpTarget(null, Objects.requireNonNull(name, "name"));
    }

    public ArtifactId id() {
        return id;
    }

    public String name() {
        return name;
    }

    public boolean isAny() {
        return id == null && name == null;
    }

    @Override
    public String toString() {
        return id != null ? "artifact_id(" + id + ")" : name != null ? "artifact_name(" + name + ")" : "any";
    }
}
