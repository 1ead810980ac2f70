package jacabot.cartago;

import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** An out port of an artifact: {@code linkArtifacts(Id, "name", Other)} links it, {@code execLinkedOp("name", ...)} uses it. */
@Retention(RetentionPolicy.RUNTIME)
@Target({})
public @interface OUTPORT {
    String name();
}
