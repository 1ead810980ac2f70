package jacabot.cartago;

import java.lang.reflect.Method;

/**
 * One operation of an artifact class: the method, whether it is internal, and its guard.
 *
 * @param method the annotated method, made accessible
 * @param internal whether it is an {@link INTERNAL_OPERATION}
 * @param guard the {@link GUARD} method checked before it starts, or null
 */
record OpMethod(Method method, boolean internal, Method guard) {
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
