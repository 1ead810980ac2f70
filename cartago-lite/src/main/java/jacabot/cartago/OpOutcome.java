package jacabot.cartago;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/** How an operation ended, as reported to the {@link OpCallback} of the caller. */
public sealed interface OpOutcome permits OpOutcome.Success, OpOutcome.Failure {

    /** {@return whether the operation succeeded} */
    boolean succeeded();

    /**
     * The operation completed.
     *
     * @param outputs the values set on the call's {@link OpFeedbackParam} arguments, by argument
     *     index (0-based); an output the operation never set is absent
     */
    record Success(Map<Integer, Object> outputs) implements OpOutcome {
        public Success {
            outputs = Collections.unmodifiableMap(new LinkedHashMap<>(outputs));
        }

        @Override
        public boolean succeeded() {
            return true;
        }
    }

    /**
     * The operation failed: by {@code failed(...)} in the artifact, by an exception, or before it
     * started (unknown operation, bad arguments...). JaCa maps it to {@code error(action_failed)},
     * {@code error_msg(message)} and, when a reason is given,
     * {@code env_failure_reason(reasonFunctor(reasonArgs...))}.
     *
     * @param message a human-readable message
     * @param reasonFunctor the functor of the reason term, or null when none was given
     * @param reasonArgs the reason's arguments as plain Java values
     */
    record Failure(String message, String reasonFunctor, List<Object> reasonArgs) implements OpOutcome {
        public Failure {
            Objects.requireNonNull(message, "message");
            reasonArgs = Values.listOf(reasonArgs.toArray());
        }

        /** {@return a failure the runtime raises itself, with reason {@code functor(args...)}} */
        static Failure of(String message, String functor, Object... args) {
            return new Failure(message, functor, Values.listOf(args));
        }

        @Override
        public boolean succeeded() {
            return false;
        }
    }
}
