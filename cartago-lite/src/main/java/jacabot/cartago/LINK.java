package jacabot.cartago;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks an artifact method as a linked operation: called by another artifact through
 * {@link Artifact#execLinkedOp(ArtifactId, String, Object...)}, never directly by agents.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface LINK {
    /** {@return the name of the guard that must hold before the operation starts, or ""} */
    String guard() default "";
}
