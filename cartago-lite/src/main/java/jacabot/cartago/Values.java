package jacabot.cartago;

import java.lang.reflect.Array;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Collection;
import java.util.List;

/** Helpers on the plain Java values that flow through artifacts: equality, normalising, printing. */
final class Values {
    private Values() {
    }

    /**
     * {@return whether two values denote the same term: numbers compare by numeric value (an
     * {@code Integer 1} equals a {@code Double 1.0}), lists and arrays element by element}
     */
    static boolean same(Object a, Object b) {
        if (a instanceof Number && b instanceof Number) {
            return ((Number) a).doubleValue() == ((Number) b).doubleValue();
        }
        List<?> la = asList(a);
        List<?> lb = asList(b);
        if (la != null && lb != null) {
            if (la.size() != lb.size()) {
                return false;
            }
            for (int i = 0; i < la.size(); i++) {
                if (!same(la.get(i), lb.get(i))) {
                    return false;
                }
            }
            return true;
        }
        return a == null ? b == null : a.equals(b);
    }

    /** {@return an unmodifiable copy of {@code values}, which may hold nulls} */
    static List<Object> listOf(Object[] values) {
        return Collections.unmodifiableList(new ArrayList<>(Arrays.asList(values)));
    }

    /** {@return whether two value tuples are the same, as in {@link #same(Object, Object)}} */
    static boolean sameAll(Object[] a, Object[] b) {
        // as same(List, List), without the two views: every property update at a commit comes here
        if (a.length != b.length) {
            return false;
        }
        for (int i = 0; i < a.length; i++) {
            if (!same(a[i], b[i])) {
                return false;
            }
        }
        return true;
    }

    /** {@return a list view of a list or array, or null for anything else} */
    static List<?> asList(Object value) {
        if (value instanceof List) {
            return (List<?>) value;
        }
        if (value != null && value.getClass().isArray()) {
            int length = Array.getLength(value);
            List<Object> list = new ArrayList<>(length);
            for (int i = 0; i < length; i++) {
                list.add(Array.get(value, i));
            }
            return list;
        }
        if (value instanceof Collection) {
            return new ArrayList<>((Collection<?>) value);
        }
        return null;
    }

    /**
     * {@return the value with its numbers normalised for an untyped ({@code Object}) parameter: an
     * integral number becomes an Integer (a Long beyond int's range), any other a Double; never a
     * Byte, Short or Float. Lists are normalised element by element}
     */
    static Object normalise(Object value) {
        if (value instanceof Number) {
            double d = ((Number) value).doubleValue();
            if (d == Math.rint(d) && !Double.isInfinite(d)) {
                if (d >= Integer.MIN_VALUE && d <= Integer.MAX_VALUE) {
                    return (int) d;
                }
                if (value instanceof Long) {
                    return value;
                }
                if (d >= Long.MIN_VALUE && d <= Long.MAX_VALUE) {
                    return (long) d;
                }
            }
            return d;
        }
        if (value instanceof List) {
            List<Object> out = new ArrayList<>();
            for (Object element : (List<?>) value) {
                out.add(normalise(element));
            }
            return out;
        }
        return value;
    }

    /** {@return the value as AgentSpeak would print it: strings quoted, integral numbers without ".0"} */
    static String show(Object value) {
        if (value instanceof String) {
            return "\"" + value + "\"";
        }
        return text(value);
    }

    /** {@return the value as a console prints it: like {@link #show(Object)} but strings unquoted} */
    static String text(Object value) {
        if (value instanceof Double || value instanceof Float) {
            double d = ((Number) value).doubleValue();
            if (d == Math.rint(d) && !Double.isInfinite(d) && Math.abs(d) < 1e15) {
                return Long.toString((long) d);
            }
            return Double.toString(d);
        }
        List<?> list = value instanceof String ? null : asList(value);
        if (list != null) {
            StringBuilder text = new StringBuilder("[");
            for (int i = 0; i < list.size(); i++) {
                text.append(i == 0 ? "" : ",").append(show(list.get(i)));
            }
            return text.append(']').toString();
        }
        return String.valueOf(value);
    }
}
