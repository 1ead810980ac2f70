package jacabot.cartago;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** CArtAgO's description of an artifact class: its out ports ({@code outports = {@OUTPORT(name = "out-1")}}). */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.TYPE)
public @interface ARTIFACT_INFO {
    OUTPORT[] outports() default {};
}
