package jacabot.cartago;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * The usage interface of an artifact class, found once by reflection: its operations, guards and
 * {@code init} methods, including inherited ones (a subclass's method hides the same signature
 * above it). Methods of one name and arity are tried in a fixed order, so that resolution does
 * not depend on the JVM's reflection order.
 */
final class ArtifactType {
    private static final Comparator<Method> ORDER = Comparator.comparing(Method::toGenericString);

    private final Class<? extends Artifact> type;
    private final Map<String, List<OpMethod>> operations = new LinkedHashMap<>();
    private final Map<String, List<Method>> guards = new LinkedHashMap<>();
    private final List<Method> inits = new ArrayList<>();
    /** The operations that never wait ({@link AwaitAnalysis}); read from the class files on first use. */
    private Set<Method> neverWaiting;

    private ArtifactType(Class<? extends Artifact> type) {
        this.type = type;
    }

    /**
     * {@return the interface of {@code type}}
     *
     * @throws IllegalArgumentException for a guard that does not exist or is not boolean
     */
    static ArtifactType of(Class<? extends Artifact> type) {
        ArtifactType result = new ArtifactType(type);
        List<Method> methods = result.methods();
        for (Method m : methods) {
            if (m.isAnnotationPresent(GUARD.class)) {
                if (m.getReturnType() != boolean.class && m.getReturnType() != Boolean.class) {
                    throw new IllegalArgumentException("guard " + m.getName() + " of " + type.getName() + " must return boolean");
                }
                result.guards.computeIfAbsent(m.getName(), k -> new ArrayList<>()).add(m);
            }
            if (m.getName().equals("init") && !Modifier.isStatic(m.getModifiers())) {
                result.inits.add(m);
            }
        }
        for (Method m : methods) {
            OPERATION op = m.getAnnotation(OPERATION.class);
            INTERNAL_OPERATION internal = m.getAnnotation(INTERNAL_OPERATION.class);
            LINK link = m.getAnnotation(LINK.class);
            String guardName = op != null ? op.guard() : internal != null ? internal.guard() : link != null ? link.guard() : null;
            if (guardName != null) {
                OpMethod.Kind kind = op != null ? OpMethod.Kind.OPERATION
                        : internal != null ? OpMethod.Kind.INTERNAL : OpMethod.Kind.LINK;
                Method guard = guardName.isEmpty() ? null : result.guardFor(guardName, m);
                result.operations.computeIfAbsent(m.getName(), k -> new ArrayList<>()).add(new OpMethod(m, kind, guard));
            }
        }
        return result;
    }

    /** The declared methods of the class and its ancestors up to Artifact, most derived first. */
    private List<Method> methods() {
        List<Method> all = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        for (Class<?> c = type; c != null && c != Artifact.class && c != Object.class; c = c.getSuperclass()) {
            Method[] declared = c.getDeclaredMethods();
            Arrays.sort(declared, ORDER);
            for (Method m : declared) {
                String key = m.getName() + Arrays.toString(m.getParameterTypes());
                if (!m.isSynthetic() && !m.isBridge() && seen.add(key)) {
                    m.setAccessible(true);
                    all.add(m);
                }
            }
        }
        return all;
    }

    private Method guardFor(String name, Method op) {
        for (Method g : guards.getOrDefault(name, List.of())) {
            if (g.getParameterCount() == op.getParameterCount()) {
                return g;
            }
        }
        throw new IllegalArgumentException("operation " + op.getName() + " of " + type.getName()
                + " names guard " + name + ", but no @GUARD " + name + " with "
                + op.getParameterCount() + " parameter(s) exists");
    }

    /** {@return whether {@code op} never waits, so that a stepped workspace may run it on the caller's thread} */
    synchronized boolean neverWaits(OpMethod op) {
        if (neverWaiting == null) {
            List<Method> all = new ArrayList<>();
            operations.values().forEach(ops -> ops.forEach(o -> all.add(o.method())));
            neverWaiting = AwaitAnalysis.neverWaiting(type, all);
        }
        return op.guard() == null && neverWaiting.contains(op.method());
    }

    Class<? extends Artifact> type() {
        return type;
    }

    /** {@return the operations agents may use (the usage interface), as name/arity, sorted} */
    List<String> usageInterface() {
        Set<String> out = new TreeSet<>();
        operations.forEach((name, ops) -> ops.stream().filter(o -> o.kind() == OpMethod.Kind.OPERATION)
                .forEach(o -> out.add(name + "/" + o.method().getParameterCount())));
        return List.copyOf(out);
    }

    /** {@return the methods called {@code name}, of every kind, in the order {@link #operations} keeps them (not a copy)} */
    List<OpMethod> named(String name) {
        return operations.getOrDefault(name, List.of());
    }

    /** {@return the operations called {@code name}, of any arity, of the given kinds in that order} */
    List<OpMethod> operations(String name, OpMethod.Kind... kinds) {
        List<OpMethod> found = new ArrayList<>();
        for (OpMethod.Kind kind : kinds) {
            for (OpMethod op : operations.getOrDefault(name, List.of())) {
                if (op.kind() == kind) {
                    found.add(op);
                }
            }
        }
        return found;
    }

    /** {@return the guards called {@code name} that take {@code count} arguments} */
    List<Method> guards(String name, int count) {
        List<Method> found = new ArrayList<>();
        for (Method g : guards.getOrDefault(name, List.of())) {
            if (ArgConverter.acceptsArity(g, count)) {
                found.add(g);
            }
        }
        return found;
    }

    /** {@return the {@code init} methods that take {@code count} arguments} */
    List<Method> inits(int count) {
        List<Method> found = new ArrayList<>();
        for (Method m : inits) {
            if (ArgConverter.acceptsArity(m, count)) {
                found.add(m);
            }
        }
        return found;
    }
}
