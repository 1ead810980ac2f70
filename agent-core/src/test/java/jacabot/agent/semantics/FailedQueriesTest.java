package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.testing.TestAgent;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Plan contexts that begin with a rule query known to fail ({@link FailedQueries}) choose the plans,
 * print the lines and number the later fresh variables as contexts whose query is asked each time: the
 * same program with a fact first in every context (so that the query is not the context's first
 * literal and is always proved) is the reference.
 */
class FailedQueriesTest {
    private static final String PROGRAM = """
            f.
            q(1, 2).
            q(2, 30).
            r(X) :- limit(L) & q(X, Y) & Y > L.
            s(X) :- .my_name(N) & q(X, _).
            limit(100).
            !g.
            +!g <- !h(_); !t(a); !t(b); !h(_); -+limit(20); !t(c); !t(d); !u; !u; !h(_); -+limit(100); !t(e); !h(_); .stopMAS.
            +!t(W) : F r(A) & A > 1 <- .print(W, " one ", A).
            +!t(W) : F r(B) <- .print(W, " two ", B).
            +!t(W) : F r(_) & true <- .print(W, " three").
            +!t(W) <- .print(W, " none").
            +!u : F s(7) <- .print(seven).
            +!u : F s(8) <- .print(eight).
            +!u <- .print(neither).
            +!h(A) <- .intention(_, _, [im(_, T, _, _)|_], current); .print(T).
            """;

    private static TestAgent run(String first) {
        var a = new TestAgent(PROGRAM.replace("F ", first));
        a.cycles(500);
        return a;
    }

    @Test
    void contextsAnsweredByFailedQueriesChooseAndNumberAsContextsProvedEachTime() {
        TestAgent remembered = run("");
        TestAgent proved = run("f & ");
        List<String> out = remembered.printed();
        assertEquals(proved.printed(), out);
        assertEquals(List.of("a none", "b none", "c one 2", "d one 2", "neither", "neither", "e none"),
                out.stream().filter(l -> !l.startsWith("{")).toList(), out.toString());
        // r(_) failed in !t(a)'s first context, then was answered in its two other plans' contexts and in
        // the three of !t(b) (nothing believed changed in between); again so for !t(e) once limit(100)
        // was back; s(_) runs an internal action, so it is proved each time
        assertEquals(7, remembered.agent.solver().failedQueries.answered());
        assertEquals(0, proved.agent.solver().failedQueries.answered());
    }
}
