package jacabot.cartago;

import java.lang.reflect.Array;
import java.lang.reflect.Executable;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;

/**
 * Converts the plain Java values of a call to the parameter types of an artifact method, as
 * CArtAgO does: any number fits a numeric parameter when its value does (an {@code int} accepts
 * {@code 5.0}, not {@code 5.5}); an {@code Object} parameter gets numbers normalised to Integer,
 * Long or Double (never Byte); strings fit enums by name; lists and arrays fit each other;
 * {@link OpFeedbackParam} arguments (unbound variables) only fit {@code OpFeedbackParam} and
 * {@code Object} parameters. Varargs methods
 * receive their trailing arguments packed into an array.
 */
final class ArgConverter {
    private ArgConverter() {
    }

    /** A value that does not fit its parameter; the message says which and why. */
    static final class Mismatch extends Exception {
        private static final long serialVersionUID = 1L;
        final int index;

        Mismatch(int index, String message) {
            super(message, null, false, false);
            this.index = index;
        }
    }

    /** {@return whether a method takes {@code count} arguments, counting varargs} */
    static boolean acceptsArity(Executable method, int count) {
        int arity = method.getParameterCount();
        return count == arity || method.isVarArgs() && count >= arity - 1;
    }

    /** {@return the arguments converted for {@code method}, which accepts their number} */
    static Object[] convertAll(Executable method, Object[] args) throws Mismatch {
        Class<?>[] types = method.getParameterTypes();
        Object[] out = new Object[types.length];
        int fixed = method.isVarArgs() ? types.length - 1 : types.length;
        for (int i = 0; i < fixed; i++) {
            out[i] = convert(i, args[i], types[i]);
        }
        if (method.isVarArgs()) {
            Class<?> arrayType = types[fixed];
            if (args.length == types.length && args[fixed] != null && args[fixed].getClass() == arrayType) {
                out[fixed] = args[fixed];
            } else {
                Class<?> component = arrayType.getComponentType();
                Object packed = Array.newInstance(component, args.length - fixed);
                for (int i = fixed; i < args.length; i++) {
                    Array.set(packed, i - fixed, convert(i, args[i], component));
                }
                out[fixed] = packed;
            }
        }
        return out;
    }

    /** {@return {@code value} converted to {@code type}}, argument {@code index} being 0-based */
    static Object convert(int index, Object value, Class<?> type) throws Mismatch {
        Class<?> boxed = box(type);
        if (value instanceof OpFeedbackParam) {
            if (boxed == OpFeedbackParam.class || boxed == Object.class) {
                return value;   // an Object parameter takes an unbound variable too (TupleSpace's in/rd)
            }
            throw mismatch(index, "is an unbound output, but the parameter is an input of type " + name(type));
        }
        if (boxed == OpFeedbackParam.class) {
            throw mismatch(index, "must be an unbound variable (an output), got " + Values.show(value));
        }
        if (value == null) {
            if (type.isPrimitive()) {
                throw mismatch(index, "expected " + name(type) + ", got null");
            }
            return null;
        }
        if (boxed == Object.class || boxed == Number.class && value instanceof Number) {
            return Values.normalise(value);
        }
        if (value instanceof Number && Number.class.isAssignableFrom(boxed)) {
            return number(index, (Number) value, boxed);
        }
        if (boxed == String.class && (value instanceof CharSequence || value instanceof Enum)) {
            return value instanceof Enum ? ((Enum<?>) value).name() : value.toString();
        }
        if (boxed == Character.class && value instanceof CharSequence && ((CharSequence) value).length() == 1) {
            return ((CharSequence) value).charAt(0);
        }
        if (boxed.isEnum() && value instanceof CharSequence) {
            return enumConstant(index, value.toString(), boxed);
        }
        if (boxed.isArray() && !boxed.isInstance(value) && Values.asList(value) != null) {
            return array(index, Values.asList(value), boxed.getComponentType());
        }
        if ((boxed == List.class || boxed == Collection.class || boxed == Iterable.class)
                && !boxed.isInstance(value) && Values.asList(value) != null) {
            return new ArrayList<>(Values.asList(value));
        }
        if (boxed.isInstance(value)) {
            return value;
        }
        throw mismatch(index, "expected " + name(type) + ", got " + Values.show(value)
                + " (" + value.getClass().getSimpleName() + ")");
    }

    private static Object number(int index, Number value, Class<?> boxed) throws Mismatch {
        double d = value.doubleValue();
        if (boxed == Double.class) {
            return d;
        }
        if (boxed == Float.class) {
            return (float) d;
        }
        boolean integral = d == Math.rint(d) && !Double.isInfinite(d);
        long l = value instanceof Long ? value.longValue() : (long) d;
        if (boxed == Integer.class && integral && d >= Integer.MIN_VALUE && d <= Integer.MAX_VALUE) {
            return (int) l;
        }
        if (boxed == Long.class && integral && d >= Long.MIN_VALUE && d <= Long.MAX_VALUE) {
            return l;
        }
        if (boxed == Short.class && integral && d >= Short.MIN_VALUE && d <= Short.MAX_VALUE) {
            return (short) l;
        }
        if (boxed == Byte.class && integral && d >= Byte.MIN_VALUE && d <= Byte.MAX_VALUE) {
            return (byte) l;
        }
        if (boxed.isInstance(value)) {
            return value;
        }
        throw mismatch(index, "expected " + boxed.getSimpleName().toLowerCase(Locale.ROOT)
                + ", got " + Values.show(value) + " which does not fit");
    }

    private static Object enumConstant(int index, String text, Class<?> type) throws Mismatch {
        Object[] constants = type.getEnumConstants();
        for (Object constant : constants) {
            if (((Enum<?>) constant).name().equals(text)) {
                return constant;
            }
        }
        for (Object constant : constants) {
            if (((Enum<?>) constant).name().equalsIgnoreCase(text)) {
                return constant;
            }
        }
        throw mismatch(index, "expected a constant of " + type.getSimpleName() + ", got " + Values.show(text));
    }

    private static Object array(int index, List<?> values, Class<?> component) throws Mismatch {
        Object array = Array.newInstance(component, values.size());
        for (int i = 0; i < values.size(); i++) {
            try {
                Array.set(array, i, convert(index, values.get(i), component));
            } catch (Mismatch e) {
                throw mismatch(index, "element " + (i + 1) + " " + e.getMessage().replaceFirst("^argument \\d+ ", ""));
            }
        }
        return array;
    }

    private static Mismatch mismatch(int index, String message) {
        return new Mismatch(index, "argument " + (index + 1) + " " + message);
    }

    private static String name(Class<?> type) {
        return type.getSimpleName();
    }

    static Class<?> box(Class<?> type) {
        if (!type.isPrimitive()) {
            return type;
        }
        if (type == int.class) {
            return Integer.class;
        }
        if (type == long.class) {
            return Long.class;
        }
        if (type == double.class) {
            return Double.class;
        }
        if (type == float.class) {
            return Float.class;
        }
        if (type == boolean.class) {
            return Boolean.class;
        }
        if (type == short.class) {
            return Short.class;
        }
        if (type == byte.class) {
            return Byte.class;
        }
        if (type == char.class) {
            return Character.class;
        }
        return Void.class;
    }
}
