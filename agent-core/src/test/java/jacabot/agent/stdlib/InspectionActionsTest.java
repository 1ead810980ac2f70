package jacabot.agent.stdlib;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.agent.testing.TestAgent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code .relevant_plan}, {@code .get_src_info}, {@code .save_agent} and
 * {@code .drop_future_intention}, one behaviour each (jason-oracle/34 and 36 hold more).
 */
class InspectionActionsTest {
    @Test
    void relevantPlanGivesEachPlanAsWrittenWithoutBraces() {
        var a = new TestAgent("""
                !g.
                @pa +!a(X) : X > 0 <- .print(X).
                @pb +!a(X) <- .print(any).
                +!g <- for (.relevant_plan({+!a(1)}, P)) { .plan_label(P, L); .print(L) };
                       .relevant_plan({+!a(_)}, Q); .print(Q).
                """);
        a.cycles(20);
        assertEquals(List.of("pa[source(self)]", "pb[source(self)]",
                "@pa[source(self)] +!a(X) : (X > 0) <- .print(X)."), a.printed().stream()
                .map(s -> s.replaceAll(",url\\(\"[^\"]*\"\\)", "")).toList());
    }

    @Test
    void getSrcInfoGivesWhereTheLiteralWasWrittenNotWhereItIsAsked() {
        var a = new TestAgent("""
                b(c(7)).
                !g.
                +!g <- X = b(1)[k];
                       .print(x);
                       .get_src_info(X, R); .print(R);
                       ?b(C); .get_src_info(C, S); .print(S);
                       Y =.. [f, [1], []]; .get_src_info(Y, T); .print(T).
                """);
        a.cycles(20);
        assertEquals(List.of("x", "b(1)[code_line(3),code_src(\"file:bob.asl\"),k]",
                "c(7)[code_line(1),code_src(\"file:bob.asl\")]", "f(1)[code_line(no_code),code_src(no_code)]"), a.printed());
    }

    @Test
    void saveAgentWritesBeliefsInJasonsOrderGoalsAndPlans(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("saved.asl");
        var a = new TestAgent("""
                b(1).
                b(2)[x].
                c("s").
                d :- b(X) & X > 1.
                !start.
                @ps +!start <- +e(3); .save_agent("%s", [g(1), h]).
                """.formatted(file.toString().replace("\\", "\\\\")));
        a.cycles(10);
        String text = Files.readString(file).replaceAll(",url\\(\"[^\"]*\"\\)", "");
        // Jason 3.2.0's file for the same agent (jason-oracle's save_agent run), without its four
        // kqml:: rules: e/1, c/1, d/0, b/1 is the order of its hash map's bins
        assertEquals("""
                // beliefs and rules
                e(3).
                c("s").
                d :- (b(X) & (X > 1)).
                b(1).
                b(2)[x].


                // initial goals
                !g(1).
                !h.


                // plans from file:%s

                @ps[source(self)] +!start <- +e(3); .save_agent("%s",[g(1),h]).

                """.formatted("bob.asl", file.toString().replace("\\", "\\\\")), text);
    }

    @Test
    void dropFutureIntentionDropsIntentionsWhosePlanPostsTheGoal() {
        var a = new TestAgent("""
                !w(1). !w(2). !o. !g.
                +!w(N) <- .wait(50); !s(N); .print(w(N)).
                +!o <- .wait(50); !s(3); .print(o).
                +!s(N) <- .print(s(N)).
                +!g <- .wait(10); .drop_future_intention(s(1)); .print(dropped).
                """);
        a.cycles(20).advance(20, 50).advance(100, 100);
        // the plans of w are written !s(N), which unifies with s(1) for both: Jason drops both
        assertEquals(List.of("dropped", "s(3)", "o"), a.printed());
    }

    @Test
    void unknownInternalActionsAreReportedBeforeTheFirstStepAndRunAsActions() {
        var a = new TestAgent("""
                !g.
                +!g <- .print(a); lib.known(1); .unknown(2).
                -!g[error(E)] <- .print(E).
                """);
        // a library's action added by the architecture before the agent runs is known
        a.agent.addInternalAction("lib.known", (ag, un, args) -> true);
        a.cycles(20);
        assertEquals("[aslparser] [file:bob.asl:2] warning: The internal action class for '.unknown(2)' was not"
                + " loaded! Error: java.lang.ClassNotFoundException: jason.stdlib.unknown", a.console.get(0));
        assertEquals(List.of("a"), a.printed().subList(1, 2));
        assertEquals(List.of(".unknown(2)"), a.actionNames(), "run as an environment action");
    }
}
