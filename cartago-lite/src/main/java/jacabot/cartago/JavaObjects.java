package jacabot.cartago;

import java.lang.reflect.Array;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * CArtAgO's Java data binding on the runtime's side: making objects and calling their public
 * methods with the arguments converted as operation arguments are (numbers to any numeric type
 * whose range holds them, lists to arrays, ...). The JaCa bridge's {@code cartago.new_obj} and
 * {@code cartago.invoke_obj} use it. Every failure is a {@link JavaCallException} whose message
 * names the class, the member and why.
 */
public final class JavaObjects {
    private JavaObjects() {
    }

    /** A call that could not be made or that threw; the message is meant for the agent. */
    public static final class JavaCallException extends Exception {
        private static final long serialVersionUID = 1L;

        JavaCallException(String message) {
            super(message);
        }
    }

    /** {@return the class called {@code name} (primitive names too), through {@code loader}} */
    public static Class<?> load(String name, ClassLoader loader) throws JavaCallException {
        switch (name) {
            case "int": return int.class;
            case "long": return long.class;
            case "double": return double.class;
            case "float": return float.class;
            case "boolean": return boolean.class;
            case "char": return char.class;
            case "short": return short.class;
            case "byte": return byte.class;
            default:
        }
        try {
            return Class.forName(name, true, loader);
        } catch (ClassNotFoundException | LinkageError e) {
            throw new JavaCallException("class " + name + " not found");
        }
    }

    /** {@return a new instance of {@code type} made by its first public constructor the arguments fit} */
    public static Object newInstance(Class<?> type, Object[] args) throws JavaCallException {
        if (Modifier.isAbstract(type.getModifiers())) {
            throw new JavaCallException("class " + type.getName() + " is abstract");
        }
        var candidates = Arrays.asList(type.getConstructors());
        Constructor<?> c = (Constructor<?>) pick(candidates, args);
        if (c == null) {
            throw new JavaCallException("class " + type.getName() + " has no public constructor for " + shown(args));
        }
        try {
            return c.newInstance(ArgConverter.convertAll(c, args));
        } catch (ArgConverter.Mismatch | ReflectiveOperationException e) {
            throw failure(type.getName() + "(" + shown(args) + ")", e);
        }
    }

    /**
     * Calls the public method {@code name} on {@code target}, or the static one of {@code type} when
     * {@code target} is null. {@return its result, null for void}
     */
    public static Object invoke(Object target, Class<?> type, String name, Object[] args) throws JavaCallException {
        var candidates = new ArrayList<Executable>();
        for (Method m : type.getMethods()) {
            if (m.getName().equals(name) && (target != null || Modifier.isStatic(m.getModifiers()))) {
                candidates.add(m);
            }
        }
        Method m = (Method) pick(candidates, args);
        if (m == null) {
            throw new JavaCallException((target == null ? "no public static method " : "no public method ")
                    + type.getName() + "." + name + " for (" + shown(args) + ")");
        }
        try {
            m.setAccessible(true);   // a public method of a non-public class (e.g. a JDK implementation)
        } catch (RuntimeException notOpen) {
            // the module system refuses: the plain call below says so
        }
        try {
            return m.invoke(target, ArgConverter.convertAll(m, args));
        } catch (ArgConverter.Mismatch | ReflectiveOperationException e) {
            throw failure(type.getName() + "." + name + "(" + shown(args) + ")", e);
        }
    }

    /** {@return an array of {@code component} holding {@code values}, each converted} */
    public static Object newArray(Class<?> component, List<?> values) throws JavaCallException {
        Object array = Array.newInstance(component, values.size());
        for (int i = 0; i < values.size(); i++) {
            try {
                Array.set(array, i, ArgConverter.convert(i, values.get(i), component));
            } catch (ArgConverter.Mismatch e) {
                throw new JavaCallException("element " + (i + 1) + ": " + e.getMessage());
            }
        }
        return array;
    }

    /**
     * The candidate whose parameters the arguments are instances of, else the first (in a stable
     * order: varargs last) whose parameters they convert to: an array passed in stays that array.
     */
    private static Executable pick(List<? extends Executable> candidates, Object[] args) {
        var sorted = new ArrayList<Executable>(candidates);
        sorted.sort((a, b) -> a.isVarArgs() == b.isVarArgs() ? a.toString().compareTo(b.toString())
                : a.isVarArgs() ? 1 : -1);
        for (Executable e : sorted) {
            if (!e.isVarArgs() && e.getParameterCount() == args.length && instancesOf(e, args)) {
                return e;
            }
        }
        for (Executable e : sorted) {
            if (!ArgConverter.acceptsArity(e, args.length)) {
                continue;
            }
            try {
                ArgConverter.convertAll(e, args);
                return e;
            } catch (ArgConverter.Mismatch tryNext) {
                // another overload may fit
            }
        }
        return null;
    }

    /** Numbers count only for their own type (agents' numbers are all Double); other values for any supertype. */
    private static boolean instancesOf(Executable e, Object[] args) {
        Class<?>[] types = e.getParameterTypes();
        for (int i = 0; i < args.length; i++) {
            Object a = args[i];
            Class<?> boxed = ArgConverter.box(types[i]);
            boolean fits = a == null ? !types[i].isPrimitive()
                    : a instanceof Number ? boxed == a.getClass() : boxed.isInstance(a);
            if (!fits) {
                return false;
            }
        }
        return true;
    }

    private static JavaCallException failure(String call, Exception e) {
        if (e instanceof InvocationTargetException ite && ite.getCause() != null) {
            Throwable t = ite.getCause();
            return new JavaCallException(call + " threw " + t.getClass().getName()
                    + (t.getMessage() == null ? "" : ": " + t.getMessage()));
        }
        return new JavaCallException(call + ": " + e.getMessage());
    }

    private static String shown(Object[] args) {
        var parts = new ArrayList<String>();
        for (Object a : args) {
            parts.add(Values.show(a));
        }
        return String.join(", ", parts);
    }
}
