package jacabot.cartago;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Method;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Which operations of an artifact class never wait, read from its class files. The stepped
 * scheduler runs those on its own thread instead of handing each to a carrier thread and back: two
 * thread wake-ups fewer per agent action, a third of a lockstep control step.
 *
 * <p>Conservative: an operation never waits when no method it can reach calls a primitive that
 * waits ({@code await}, {@code await_time}, {@code execLinkedOp}, {@code delay}, {@code makeArtifact},
 * {@code dispose(id)}, {@code beginExternalSession}). It follows calls into the artifact's class and
 * its superclasses up to {@link Artifact}, their nested classes (all of a nested class's methods,
 * lambdas included) and the classes of their packages, the only code that may call those protected
 * primitives. A class file that cannot be read makes an operation "may wait". Should code beyond
 * that reach an {@code await} anyway (through a public method of the artifact), the operation fails
 * with a clear message (it runs inline) rather than hang.
 */
final class AwaitAnalysis {
    private static final String ARTIFACT = "jacabot/cartago/Artifact";
    private static final Set<String> WAITING = Set.of("await", "await_time", "execLinkedOp", "delay", "makeArtifact",
            "beginExternalSession", "dispose(Ljacabot/cartago/ArtifactId;)V");

    private final ClassLoader loader;
    private final List<String> hierarchy;
    private final Set<String> packages = new HashSet<>();
    /** Internal class name → its methods' calls; null for a class that could not be read. */
    private final Map<String, Map<String, List<ClassFileCalls.Call>>> classes = new HashMap<>();

    private AwaitAnalysis(Class<? extends Artifact> type, ClassLoader loader) {
        this.loader = loader;
        List<String> names = new ArrayList<>();
        for (Class<?> c = type; c != null && c != Artifact.class && c != Object.class; c = c.getSuperclass()) {
            String name = c.getName().replace('.', '/');
            names.add(name);
            packages.add(name.substring(0, Math.max(0, name.lastIndexOf('/'))));
        }
        this.hierarchy = List.copyOf(names);
    }

    /** {@return those of {@code ops} (methods of {@code type}) that never wait} */
    static Set<Method> neverWaiting(Class<? extends Artifact> type, Collection<Method> ops) {
        return neverWaiting(type, ops, type.getClassLoader() != null ? type.getClassLoader() : ClassLoader.getSystemClassLoader());
    }

    /** As {@link #neverWaiting(Class, Collection)}, reading the class files through {@code loader}. */
    static Set<Method> neverWaiting(Class<? extends Artifact> type, Collection<Method> ops, ClassLoader loader) {
        AwaitAnalysis analysis = new AwaitAnalysis(type, loader);
        Set<Method> result = new HashSet<>();
        for (Method op : ops) {
            if (!analysis.mayWait(op.getName() + descriptor(op))) {
                result.add(op);
            }
        }
        return result;
    }

    /** {@return whether the operation {@code method} (name + descriptor), declared in the artifact's classes, may wait} */
    private boolean mayWait(String method) {
        Deque<String[]> todo = new ArrayDeque<>();
        Set<String> seen = new LinkedHashSet<>();
        for (String c : hierarchy) { // its declaration is among them; invoked by reflection, it runs any override
            todo.add(new String[] {c, method});
        }
        while (!todo.isEmpty()) {
            String[] next = todo.poll();
            if (!seen.add(next[0] + '.' + next[1])) {
                continue;
            }
            Map<String, List<ClassFileCalls.Call>> methods = load(next[0]);
            if (methods == null) {
                return true;
            }
            Collection<List<ClassFileCalls.Call>> bodies = next[1] == null ? methods.values()
                    : methods.containsKey(next[1]) ? List.of(methods.get(next[1])) : List.of();
            for (List<ClassFileCalls.Call> body : bodies) {
                for (ClassFileCalls.Call call : body) {
                    String key = call.name() + call.descriptor();
                    if ((call.owner().equals(ARTIFACT) || hierarchy.contains(call.owner()))
                            && (WAITING.contains(call.name()) || WAITING.contains(key))) {
                        return true;
                    }
                    if (hierarchy.contains(call.owner())) {
                        for (String c : hierarchy) { // any override of it in the artifact's classes
                            todo.add(new String[] {c, key});
                        }
                    } else if (isNested(call.owner())) {
                        todo.add(new String[] {call.owner(), null}); // all of it: any method may be called later
                    } else if (!call.owner().startsWith("[") && packages.contains(packageOf(call.owner()))
                            && !call.owner().equals(ARTIFACT)) {
                        todo.add(new String[] {call.owner(), call.name().equals("<new>") ? null : key});
                    }
                }
            }
        }
        return false;
    }

    private boolean isNested(String owner) {
        for (String c : hierarchy) {
            if (owner.startsWith(c + '$')) {
                return true;
            }
        }
        return false;
    }

    private static String packageOf(String internalName) {
        return internalName.substring(0, Math.max(0, internalName.lastIndexOf('/')));
    }

    private Map<String, List<ClassFileCalls.Call>> load(String internalName) {
        if (classes.containsKey(internalName)) {
            return classes.get(internalName);
        }
        Map<String, List<ClassFileCalls.Call>> methods;
        try (InputStream in = loader.getResourceAsStream(internalName + ".class")) {
            methods = in == null ? null : ClassFileCalls.read(in);
        } catch (IOException | RuntimeException e) {
            methods = null; // unreadable: "may wait"
        }
        classes.put(internalName, methods);
        return methods;
    }

    static String descriptor(Method m) {
        StringBuilder sb = new StringBuilder("(");
        for (Class<?> p : m.getParameterTypes()) {
            sb.append(descriptor(p));
        }
        return sb.append(')').append(descriptor(m.getReturnType())).toString();
    }

    private static String descriptor(Class<?> c) {
        if (c.isArray()) {
            return c.getName().replace('.', '/');
        }
        if (c.isPrimitive()) {
            return switch (c.getName()) {
                case "int" -> "I";
                case "long" -> "J";
                case "double" -> "D";
                case "float" -> "F";
                case "boolean" -> "Z";
                case "byte" -> "B";
                case "char" -> "C";
                case "short" -> "S";
                default -> "V";
            };
        }
        return "L" + c.getName().replace('.', '/') + ";";
    }
}
