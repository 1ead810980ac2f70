package jacabot.cartago;

import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Objects;

/**
 * The committed value of an observable property, as observers see it: {@code name(v1, ..., vn)}.
 * Values are plain Java objects (numbers, strings, booleans, lists, arrays, enums, ids...).
 *
 * @param name the property's name
 * @param values the property's values, unmodifiable
 */
public record PropertySnapshot(String name, List<Object> values) {
    public PropertySnapshot {
        Objects.requireNonNull(name, "name");
        values = Collections.unmodifiableList(Arrays.asList(values.toArray()));
    }

    static PropertySnapshot of(String name, Object[] values) {
        return new PropertySnapshot(name, Arrays.asList(values));
    }

    /** {@return the first value, or null for a property without values} */
    public Object value() {
        return values.isEmpty() ? null : values.get(0);
    }

    @Override
    public String toString() {
        StringBuilder text = new StringBuilder(name);
        if (!values.isEmpty()) {
            text.append('(');
            for (int i = 0; i < values.size(); i++) {
                text.append(i == 0 ? "" : ",").append(Values.show(values.get(i)));
            }
            text.append(')');
        }
        return text.toString();
    }
}
