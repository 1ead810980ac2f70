package jacabot.cartago;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks a {@code boolean} artifact method as a guard, named by
 * {@link OPERATION#guard()} or passed to {@link Artifact#await(String, Object...)}. A guard only
 * reads the artifact's state; it is re-evaluated after every commit of its artifact.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface GUARD {
}
