package jacabot.cartago;

import java.lang.reflect.Method;

/**
 * One operation of an artifact class: the method, who may call it, and its guard.
 *
 * @param method the annotated method, made accessible
 * @param kind who may call it
 * @param guard the {@link GUARD} method checked before it starts, or null
 */
record OpMethod(Method method, Kind kind, Method guard) {
    /** Who may call an operation. */
    enum Kind {
        /** Agents ({@link OPERATION}); the artifact itself and linked artifacts too. */
        OPERATION,
        /** The artifact itself only ({@link INTERNAL_OPERATION}). */
        INTERNAL,
        /** Linked artifacts only ({@link LINK}). */
        LINK
    }

    String name() {
        return method.getName();
    }

    boolean accepts(int count) {
        return ArgConverter.acceptsArity(method, count);
    }

    /** {@return "name/arity", with "+" for varargs} */
    String signature() {
        int arity = method.getParameterCount();
        return name() + "/" + (method.isVarArgs() ? (arity - 1) + "+" : String.valueOf(arity));
    }
}
