package jacabot.cartago;

import java.util.ArrayList;
import java.util.List;

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
    /** In definition order; several properties may share a name (CArtAgO allows it). */
    private final List<ObsProperty> working = new ArrayList<>();
    private List<Committed> committed = new ArrayList<>();

    PropertyStore(ArtifactCore owner) {
        this.owner = owner;
    }

    ObsProperty define(String name, Object[] values) {
        owner.checkInStep();
        ObsProperty property = new ObsProperty(this, name, values);
        working.add(property);
        return property;
    }

    /** {@return the first property called {@code name}, or null} */
    ObsProperty get(String name) {
        owner.checkInStep();
        for (ObsProperty p : working) {
            if (p.getName().equals(name)) {
                return p;
            }
        }
        return null;
    }

    /**
     * {@return the first property called {@code name} whose values match {@code template}
     * (same number; a null template value matches anything, numbers compare by value), or null}
     */
    ObsProperty getByTemplate(String name, Object[] template) {
        owner.checkInStep();
        for (ObsProperty p : working) {
            if (p.getName().equals(name) && p.matches(template)) {
                return p;
            }
        }
        return null;
    }

    boolean has(String name) {
        return get(name) != null;
    }

    void remove(String name) {
        remove(get(name), name);
    }

    void removeByTemplate(String name, Object[] template) {
        remove(getByTemplate(name, template), name);
    }

    private void remove(ObsProperty p, String name) {
        if (p == null) {
            throw new IllegalArgumentException("no observable property " + name + " in " + owner.id().name());
        }
        working.remove(p);
        p.attached = false;
    }

    void checkWritable(ObsProperty property) {
        owner.checkInStep();
        if (!property.attached) {
            throw new IllegalStateException("observable property " + property.getName() + " was removed from " + owner.id().name());
        }
    }

    private static boolean containsSame(List<ObsProperty> list, ObsProperty p) {
        for (ObsProperty q : list) {
            if (q == p) {
                return true;
            }
        }
        return false;
    }

    private Committed committedOf(ObsProperty p) {
        for (Committed c : committed) {
            if (c.property() == p) {
                return c;
            }
        }
        return null;
    }

    /** Makes the working version the committed one; {@return what observers must be told} */
    List<Change> commit() {
        if (sameProperties()) {
            return commitValues();
        }
        List<Change> changes = new ArrayList<>();
        List<Committed> next = new ArrayList<>();
        for (ObsProperty p : working) {
            Committed before = committedOf(p);
            if (before == null) {
                changes.add(new Change(null, p.snapshot()));
            } else if (!p.sameValues(before.values())) {
                changes.add(new Change(PropertySnapshot.of(p.getName(), before.values()), p.snapshot()));
            }
            next.add(new Committed(p, p.values()));
        }
        for (Committed before : committed) {
            if (!containsSame(working, before.property())) {
                changes.add(new Change(PropertySnapshot.of(before.property().getName(), before.values()), null));
            }
        }
        committed = next;
        return changes;
    }

    /** {@return whether no property was defined or removed since the last commit (the usual case)} */
    private boolean sameProperties() {
        if (working.size() != committed.size()) {
            return false;
        }
        for (int i = 0; i < working.size(); i++) {
            if (working.get(i) != committed.get(i).property()) {
                return false;
            }
        }
        return true;
    }

    /** {@link #commit()} when only values may have changed: an update replaces a property's values array. */
    private List<Change> commitValues() {
        List<Change> changes = null;
        for (int i = 0; i < working.size(); i++) {
            ObsProperty p = working.get(i);
            Committed before = committed.get(i);
            if (p.values() == before.values()) {
                continue;
            }
            if (!p.sameValues(before.values())) {
                if (changes == null) {
                    changes = new ArrayList<>();
                }
                changes.add(new Change(PropertySnapshot.of(p.getName(), before.values()), p.snapshot()));
            }
            committed.set(i, new Committed(p, p.values()));
        }
        return changes == null ? List.of() : changes;
    }

    /** Forgets every change since the last commit, including definitions and removals. */
    void rollback() {
        for (ObsProperty p : working) {
            p.attached = false;
        }
        working.clear();
        for (Committed c : committed) {
            c.property().restore(c.values());
            c.property().attached = true;
            working.add(c.property());
        }
    }

    /** {@return the committed properties, as observers know them} */
    List<PropertySnapshot> committedSnapshot() {
        List<PropertySnapshot> result = new ArrayList<>();
        for (Committed c : committed) {
            result.add(PropertySnapshot.of(c.property().getName(), c.values()));
        }
        return result;
    }
}
