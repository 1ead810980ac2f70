package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.awaiting.Waiters;
import jacabot.cartago.awaiting.WaitingSubclass;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/** Which operations never wait, read from the class files (the stepped scheduler runs those on its own thread). */
class AwaitAnalysisTest {
    private static Set<String> neverWaiting(Class<? extends Artifact> type) {
        List<Method> ops = new ArrayList<>();
        for (Class<?> c = type; c != Artifact.class; c = c.getSuperclass()) {
            for (Method m : c.getDeclaredMethods()) {
                if (m.isAnnotationPresent(OPERATION.class)) {
                    ops.add(m);
                }
            }
        }
        Set<String> names = new TreeSet<>();
        for (Method m : AwaitAnalysis.neverWaiting(type, ops)) {
            names.add(m.getDeclaringClass().getSimpleName() + "." + m.getName());
        }
        return names;
    }

    @Test
    void onlyOperationsThatCannotReachAWaitingPrimitiveAreFound() {
        // direct, through a private method, a lambda, an inner class, a helper of the package, a
        // linked operation and a blocking command all wait; guarded is found too (its guard is the
        // scheduler's concern, see ArtifactType.neverWaits)
        assertEquals(Set.of("Waiters.plain", "Waiters.withLoop", "Waiters.guarded", "Waiters.overridden"), neverWaiting(Waiters.class));
    }

    @Test
    void anOverrideThatWaitsMakesTheInheritedOperationWait() {
        assertEquals(Set.of("Waiters.plain", "Waiters.withLoop", "Waiters.guarded"), neverWaiting(WaitingSubclass.class));
    }

    @Test
    void aGuardedOperationIsHandedToACarrierAnyway() {
        ArtifactType type = ArtifactType.of(Waiters.class);
        assertTrue(type.neverWaits(type.operations("plain", OpMethod.Kind.OPERATION).get(0)));
        assertFalse(type.neverWaits(type.operations("guarded", OpMethod.Kind.OPERATION).get(0)));
        assertFalse(type.neverWaits(type.operations("direct", OpMethod.Kind.OPERATION).get(0)));
    }

    @Test
    void everyWorkspaceSharesOneAnalysisOfAClass() {
        // the class files are read once per JVM, not once per workspace (per run of a sweep)
        ArtifactType first = new ArtifactFactory(Waiters.class.getClassLoader()).typeOf(Waiters.class);
        ArtifactType second = new ArtifactFactory(ClassLoader.getSystemClassLoader()).typeOf(Waiters.class);
        assertSame(first, second);
        assertNotSame(first, new ArtifactFactory(Waiters.class.getClassLoader()).typeOf(WaitingSubclass.class));
    }

    @Test
    void aClassFileThatCannotBeReadMeansMayWait() throws IOException {
        ClassLoader blind = new ClassLoader(Waiters.class.getClassLoader()) {
            @Override
            public InputStream getResourceAsStream(String name) {
                return name.endsWith("Waiters.class") ? new ByteArrayInputStream(new byte[] {1, 2, 3}) : super.getResourceAsStream(name);
            }
        };
        assertEquals(Set.of(), AwaitAnalysis.neverWaiting(Waiters.class, List.of(methodOf("plain")), blind));
    }

    private static Method methodOf(String name) {
        for (Method m : Waiters.class.getDeclaredMethods()) {
            if (m.getName().equals(name)) {
                return m;
            }
        }
        throw new AssertionError(name);
    }

    @Test
    void theCallsOfEveryMethodOfThisProjectsArtifactsAreRead() throws IOException {
        // the reader must walk whole methods (switches, wide, invokedynamic) without losing its place
        for (Class<?> c : List.of(Artifact.class, Workspace.class, SteppedScheduler.class, ClassFileCalls.class, Waiters.class)) {
            try (InputStream in = c.getClassLoader().getResourceAsStream(c.getName().replace('.', '/') + ".class")) {
                var calls = ClassFileCalls.read(in);
                assertFalse(calls.isEmpty(), c.getName());
            }
        }
    }
}
