package jacabot.agent.stdlib;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.agent.testing.TestAgent;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * What jason-oracle/30 cannot show: Jason ends a .set/.queue/.map action on a wrong collection in a
 * NullPointerException (error {@code unknown}); ours fail with {@code wrong_arguments} and say why.
 */
class CollectionsTest {
    private static List<String> run(String program) {
        var a = new TestAgent(program);
        a.cycles(100);
        return a.printed();
    }

    @Test
    void aWrongCollectionFailsTheIntentionWithWrongArgumentsAndSaysWhy() {
        List<String> printed = run("""
                !t.
                +!t <- .set.create(S); .map.create(M); .queue.create(Q);
                   !bad(.map.put(x, a, 1)); !bad(.map.get(S, a, _)); !bad(.map.key(Q, _)); !bad(.map.clear([a]));
                   !bad(.set.remove(x, a)); !bad(.set.union(S, x)); !bad(.set.copy(M, _)); !bad(.set.to_list(Q, _));
                   !bad(.queue.to_list(S, _)); !bad(.queue.copy(x, _)); !bad(.queue.clear(M)); !bad(.member(_, M));
                   .print(done).
                +!bad(A) <- A; .print(no_failure).
                -!bad(_)[error(E), error_msg(Msg)] <- .print(E, " ", Msg).
                """);
        assertEquals(List.of(
                "wrong_arguments Wrong argument for internal action 'put': 'x' is not a map",
                "wrong_arguments Wrong argument for internal action 'get': '{}' is not a map",
                "wrong_arguments Wrong argument for internal action 'key': '[]' is not a map",
                "wrong_arguments Wrong argument for internal action 'clear': '[a]' is not a map",
                "wrong_arguments Wrong argument for internal action 'remove': 'x' is not a set",
                "wrong_arguments Wrong argument for internal action 'union': 'x' is not a list or a set",
                "wrong_arguments Wrong argument for internal action 'copy': '{}' is not a set",
                "wrong_arguments Wrong argument for internal action 'to_list': '[]' is not a set",
                "wrong_arguments Wrong argument for internal action 'to_list': '{}' is not a queue",
                "wrong_arguments Wrong argument for internal action 'copy': 'x' is not a queue",
                "wrong_arguments Wrong argument for internal action 'clear': '{}' is not a queue",
                "wrong_arguments Wrong argument for internal action 'member': second argument must be a list or a set",
                "done"), printed);
    }

    @Test
    void mathMaxAndMinOfAListSkipItsOtherItemsAsJasonDoes() {
        // recorded from Jason 3.2.0, whose largest starts at Double.MIN_VALUE: 4.9E-324 for a list of
        // negative numbers or of none
        assertEquals(List.of("4.9E-324 1 5 -3 1.7976931348623157E308 3"), run("""
                !t.
                +!t <- X = 5; .print(math.max([-1,-2]), " ", math.min([1,2]), " ", math.max([1+1, X]), " ",
                   math.min([a, -3, "s"]), " ", math.min([]), " ", math.max([a, 3])).
                """));
    }
}
