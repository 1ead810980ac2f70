package jacabot.cartago;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks an artifact method as an operation of its usage interface, callable by agents by name and
 * arity. With a {@link #guard()}, the operation waits (without holding the artifact) until the
 * named {@link GUARD} method, called with the same arguments, returns true.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface OPERATION {
    /** {@return the name of the guard that must hold before the operation starts, or ""} */
    String guard() default "";
}
