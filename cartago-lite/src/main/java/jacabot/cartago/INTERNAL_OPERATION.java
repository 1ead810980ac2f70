package jacabot.cartago;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks an artifact method as an internal operation: started only by the artifact itself through
 * {@link Artifact#execInternalOp(String, Object...)}, never by agents.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface INTERNAL_OPERATION {
    /** {@return the name of the guard that must hold before the operation starts, or ""} */
    String guard() default "";
}
