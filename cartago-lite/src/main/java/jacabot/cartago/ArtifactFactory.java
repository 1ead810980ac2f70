package jacabot.cartago;

import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.util.List;

/**
 * Makes artifacts for a workspace: loads the class, analyses it once, instantiates it with its
 * no-argument constructor and runs the {@code init} matching the parameters. Every problem becomes
 * an {@link OpFailedException} with a clear message and reason.
 */
final class ArtifactFactory {
    /**
     * The usage interface of each artifact class, analysed once per JVM: it depends on the class
     * alone, and reading its class files for the operations that never wait ({@link AwaitAnalysis})
     * cost every new workspace (every run of a sweep) about 20 ms of its first operations.
     */
    private static final ClassValue<ArtifactType> TYPES = new ClassValue<>() {
        @Override
        protected ArtifactType computeValue(Class<?> type) {
            return ArtifactType.of(type.asSubclass(Artifact.class));
        }
    };

    private final ClassLoader loader;

    ArtifactFactory(ClassLoader loader) {
        this.loader = loader;
    }

    /** {@return the artifact class called {@code className}} */
    Class<? extends Artifact> load(String className) {
        Class<?> type;
        try {
            type = Class.forName(className, true, loader);
        } catch (ClassNotFoundException | LinkageError e) {
            throw new OpFailedException("unknown artifact class " + className, "unknown_class", className);
        }
        if (!Artifact.class.isAssignableFrom(type)) {
            throw new OpFailedException("class " + className + " is not an artifact (it does not extend "
                    + Artifact.class.getName() + ")", "not_an_artifact", className);
        }
        return type.asSubclass(Artifact.class);
    }

    /** {@return the usage interface of {@code type}} */
    ArtifactType typeOf(Class<? extends Artifact> type) {
        try {
            return TYPES.get(type);
        } catch (IllegalArgumentException e) {
            throw new OpFailedException("bad artifact class " + type.getName() + ": " + e.getMessage(),
                    "bad_artifact_class", type.getName());
        }
    }

    /** {@return a new, unbound instance of {@code type}} */
    Artifact instantiate(Class<? extends Artifact> type) {
        try {
            Constructor<? extends Artifact> constructor = type.getDeclaredConstructor();
            constructor.setAccessible(true);
            return constructor.newInstance();
        } catch (ReflectiveOperationException | RuntimeException e) {
            Throwable cause = e.getCause() != null ? e.getCause() : e;
            throw new OpFailedException("cannot instantiate " + type.getName()
                    + " (it needs a no-argument constructor): " + cause, "init_failed", type.getName(), String.valueOf(cause));
        }
    }

    /** Runs the {@code init} of a bound artifact matching {@code params}, as a step that cannot suspend. */
    void init(ArtifactCore core, Object[] params) {
        String className = core.type().type().getName();
        List<Method> inits = core.type().inits(params.length);
        if (inits.isEmpty()) {
            if (params.length == 0) {
                return;
            }
            throw new OpFailedException(className + " has no init with " + params.length + " parameter(s)",
                    "init_failed", className, "no init/" + params.length);
        }
        Object[] converted = null;
        Method chosen = null;
        String mismatch = null;
        for (Method m : inits) {
            try {
                converted = ArgConverter.convertAll(m, params);
                chosen = m;
                break;
            } catch (ArgConverter.Mismatch e) {
                mismatch = mismatch == null ? e.getMessage() : mismatch;
            }
        }
        if (chosen == null) {
            throw new OpFailedException("init of " + className + ": " + mismatch, "init_failed", className, mismatch);
        }
        try {
            OpExecution.hook(core, core.id().creator()).runHook(chosen, converted);
        } catch (OpFailedException e) {
            throw new OpFailedException("init of " + className + " failed: " + e.failure().message(),
                    "init_failed", className, e.failure().message());
        } catch (RuntimeException | Error e) {
            throw new OpFailedException("init of " + className + " failed: " + e, "init_failed", className, String.valueOf(e));
        }
    }
}
