package jacabot.cartago;

import java.util.Objects;

/**
 * An observable property {@code name(v1, ..., vn)} of an artifact, as in CArtAgO. Updates are
 * made inside an operation step and become visible to observers at the next commit point; a
 * failed operation restores the values of its last commit. Values are plain Java objects and must
 * not be null; treat arrays given as values as immutable.
 */
public final class ObsProperty {
    private final PropertyStore store;
    private final String name;
    private Object[] values;
    /** Whether the property is among its artifact's working ones (kept by {@link PropertyStore}, which checks it per update). */
    boolean attached = true;

    ObsProperty(PropertyStore store, String name, Object[] values) {
        this.store = store;
        this.name = name;
        this.values = checked(values);
    }

    /** {@return the property's name} */
    public String getName() {
        return name;
    }

    /** {@return the first value (null for a property without values)} */
    public Object getValue() {
        return values.length == 0 ? null : values[0];
    }

    /** {@return the value at {@code index} (0-based)} */
    public Object getValue(int index) {
        return values[index];
    }

    /** {@return a copy of all the values} */
    public Object[] getValues() {
        return values.clone();
    }

    /** {@return the first value as an int (any number is accepted)} */
    public int intValue() {
        return number(0).intValue();
    }

    /** {@return the value at {@code index} as an int} */
    public int intValue(int index) {
        return number(index).intValue();
    }

    /** {@return the first value as a long} */
    public long longValue() {
        return number(0).longValue();
    }

    /** {@return the first value as a double} */
    public double doubleValue() {
        return number(0).doubleValue();
    }

    /** {@return the value at {@code index} as a double} */
    public double doubleValue(int index) {
        return number(index).doubleValue();
    }

    /** {@return the first value as a boolean} */
    public boolean booleanValue() {
        Object value = getValue();
        if (!(value instanceof Boolean)) {
            throw new IllegalStateException("property " + this + " does not hold a boolean");
        }
        return (Boolean) value;
    }

    /** {@return the first value as a string: a String as is, anything else as printed} */
    public String stringValue() {
        Object value = getValue();
        return value instanceof String ? (String) value : Values.text(value);
    }

    /** Replaces the first value (the only one, for a one-value property). */
    public void updateValue(Object value) {
        updateValue(0, value);
    }

    /** Replaces the value at {@code index} (0-based). */
    public void updateValue(int index, Object value) {
        store.checkWritable(this);
        if (index < 0 || index >= values.length) {
            throw new IndexOutOfBoundsException("property " + name + " has " + values.length + " value(s), no index " + index);
        }
        Object[] next = values.clone();
        next[index] = Objects.requireNonNull(value, "value");
        values = next;
    }

    /** Replaces all the values (their number may change). */
    public void updateValues(Object... newValues) {
        store.checkWritable(this);
        values = checked(newValues);
    }

    Object[] values() {
        return values;
    }

    void restore(Object[] committed) {
        values = committed;
    }

    PropertySnapshot snapshot() {
        return PropertySnapshot.of(name, values);
    }

    private Number number(int index) {
        Object value = values.length > index ? values[index] : null;
        if (!(value instanceof Number)) {
            throw new IllegalStateException("property " + this + " has no number at index " + index);
        }
        return (Number) value;
    }

    private static Object[] checked(Object[] values) {
        Object[] copy = values.clone();
        for (int i = 0; i < copy.length; i++) {
            if (copy[i] == null) {
                throw new IllegalArgumentException("observable property values must not be null (value " + (i + 1) + ")");
            }
        }
        return copy;
    }

    @Override
    public String toString() {
        return PropertySnapshot.of(name, values).toString();
    }

    /** {@return whether the values equal {@code other}'s, numerically for numbers} */
    /** {@return whether the values fit {@code template}: same number, null matching anything} */
    boolean matches(Object[] template) {
        if (template == null || template.length == 0) {
            return true;   // CArtAgO: a template without values matches by name
        }
        if (template.length != values.length) {
            return false;
        }
        for (int i = 0; i < template.length; i++) {
            if (template[i] != null && !Values.same(template[i], values[i])) {
                return false;
            }
        }
        return true;
    }

    boolean sameValues(Object[] other) {
        return Values.sameAll(values, other);
    }
}
