package jacabot.cartago;

import java.util.List;

/**
 * CArtAgO's failure of an artifact-to-artifact primitive ({@code makeArtifact},
 * {@code lookupArtifact}, {@code dispose}, {@code execLinkedOp} from inside an artifact). Unchecked
 * here (CArtAgO's is checked): code that catches it compiles either way. Left uncaught, it fails
 * the running operation with the primitive's own reason.
 */
public class OperationException extends OpFailedException {
    private static final long serialVersionUID = 1L;

    public OperationException(String message) {
        super(new OpOutcome.Failure(message, null, List.of()));
    }

    OperationException(OpOutcome.Failure failure) {
        super(failure);
    }
}
