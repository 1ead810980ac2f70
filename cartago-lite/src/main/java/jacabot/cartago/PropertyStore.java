package jacabot.cartago;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The observable properties of one artifact, in two versions: the working one that operations
 * change, and the committed one that observers have seen. {@link #commit()} turns the difference
 * into change events; {@link #rollback()} puts the committed values back into the same
 * {@link ObsProperty} objects (which artifacts often keep in fields), re-attaching removed ones.
 * Guarded by the artifact's lock.
 */
final class PropertyStore {
    /** One observable change: added (no before), updated, or removed (no after). */
    record Change(PropertySnapshot before, PropertySnapshot after) {
    }

    private record Committed(ObsProperty property, Object[] values) {
    }

    private final ArtifactCore owner;
    private final Map<String, ObsProperty> working = new LinkedHashMap<>();
    private Map<String, Committed> committed = new LinkedHashMap<>();

    PropertyStore(ArtifactCore owner) {
        this.owner = owner;
    }

    ObsProperty define(String name, Object[] values) {
        owner.checkInStep();
        if (working.containsKey(name)) {
            throw new IllegalArgumentException("observable property " + name + " is already defined in " + owner.id().name());
        }
        ObsProperty property = new ObsProperty(this, name, values);
        working.put(name, property);
        return property;
    }

    ObsProperty get(String name) {
        owner.checkInStep();
        return working.get(name);
    }

    boolean has(String name) {
        owner.checkInStep();
        return working.containsKey(name);
    }

    void remove(String name) {
        owner.checkInStep();
        if (working.remove(name) == null) {
            throw new IllegalArgumentException("no observable property " + name + " in " + owner.id().name());
        }
    }

    void checkWritable(ObsProperty property) {
        owner.checkInStep();
        if (working.get(property.getName()) != property) {
            throw new IllegalStateException("observable property " + property.getName() + " was removed from " + owner.id().name());
        }
    }

    /** Makes the working version the committed one; {@return what observers must be told} */
    List<Change> commit() {
        List<Change> changes = new ArrayList<>();
        Map<String, Committed> next = new LinkedHashMap<>();
        for (ObsProperty p : working.values()) {
            Committed before = committed.get(p.getName());
            if (before == null) {
                changes.add(new Change(null, p.snapshot()));
            } else if (!p.sameValues(before.values())) {
                changes.add(new Change(PropertySnapshot.of(p.getName(), before.values()), p.snapshot()));
            }
            next.put(p.getName(), new Committed(p, p.values()));
        }
        for (Committed before : committed.values()) {
            if (!working.containsKey(before.property().getName())) {
                changes.add(new Change(PropertySnapshot.of(before.property().getName(), before.values()), null));
            }
        }
        committed = next;
        return changes;
    }

    /** Forgets every change since the last commit, including definitions and removals. */
    void rollback() {
        working.clear();
        for (Committed c : committed.values()) {
            c.property().restore(c.values());
            working.put(c.property().getName(), c.property());
        }
    }

    /** {@return the committed properties, as observers know them} */
    List<PropertySnapshot> committedSnapshot() {
        List<PropertySnapshot> result = new ArrayList<>();
        for (Committed c : committed.values()) {
            result.add(PropertySnapshot.of(c.property().getName(), c.values()));
        }
        return result;
    }
}
