package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.testing.TestAgent;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The interpreter's shortcuts for common cases (a loop's steps, {@code .range} in a proof,
 * {@code -+b} among ground facts, a belief group emptied and filled again) do what the general
 * paths did: the expected lines are those of the build before them.
 */
class ShortcutTest {

    private static List<String> run(String program) {
        var a = new TestAgent(program);
        a.cycles(500);
        return a.printed();
    }

    @Test
    void delAddRemovesTheFirstBeliefWithTheAnnotationsAndTakesTheNumbersOfItsFreshVariables() {
        List<String> out = run("""
                !g.
                +!g <- +c(1)[source(x)]; +c(2); -+c(9);
                       .findall(b(X, S), c(X)[source(S)], L1); .print(L1);
                       -+c(7)[source(x)];
                       .findall(b(X, S), c(X)[source(S)], L2); .print(L2);
                       .stopMAS.
                """);
        assertEquals(List.of("[b(9,self),b(1,x)]", "[b(7,x),b(9,self)]"), out.subList(0, 2));
        // each !h(_) renames its variable (seen in the goal's trigger, { +!h(_27)[source(self)] });
        // -+d(1, 2) takes one number more than -+c(3) (Jason 3.2.0 prints _27, _40, _52 run alone)
        List<String> goals = run("""
                !g.
                +!g <- !h(_); -+d(1, 2); !h(_); -+c(3); !h(_).
                +!h(A) <- .intention(_, _, [im(_, T, _, _)|_], current); .print(T).
                """);
        int first = number(goals.get(0));
        int second = number(goals.get(1));
        assertEquals(1, (second - first) - (number(goals.get(2)) - second), goals.toString());
    }

    /** The number of the fresh variable in a printed goal trigger, as {@code { +!h(_27)[source(self)] }}. */
    private static int number(String printed) {
        return Integer.parseInt(printed.substring(printed.indexOf("(_") + 2, printed.indexOf(')')));
    }

    /**
     * {@code PlanLibrary.hasCandidate} of a trigger's parts keeps an answer per slot: over belief
     * events of many predicates in turn (a percept update's {@code -p}, {@code +p}, {@code -q}, ...),
     * with plans added and removed between them, every answer is the general lookup's.
     */
    @Test
    void beliefEventsAskedByTheirPartsFollowPlansAddedAndRemoved() throws Exception {
        var parser = new jacabot.agent.parser.AslParser();
        var library = new PlanLibrary();
        library.add(parser.parsePlan("@onP +p(X) <- .print(X)."), false);
        library.add(parser.parsePlan("@offQ -q <- true."), false);
        List<Literal> beliefs = new java.util.ArrayList<>();
        for (String f : List.of("p", "q", "r", "s", "t", "u", "v", "w", "x", "y")) {
            beliefs.add(Literal.of(f, new NumberTerm(1)));
            beliefs.add(Literal.atom(f));
        }
        int has = 0;
        for (int round = 0; round < 6; round++) {
            if (round == 2) { // just asked, then two others: the answer sits in its slot only
                assertEquals(false, library.hasCandidate(Trigger.Op.ADD, Trigger.Type.BELIEF, beliefs.get(4)));
                library.hasCandidate(Trigger.Op.DEL, Trigger.Type.BELIEF, beliefs.get(6));
                library.hasCandidate(Trigger.Op.ADD, Trigger.Type.BELIEF, beliefs.get(8));
                library.add(parser.parsePlan("@onR +r(X) <- true."), false);
                assertEquals(true, library.hasCandidate(Trigger.Op.ADD, Trigger.Type.BELIEF, beliefs.get(4)));
            }
            if (round == 4) {
                assertEquals(true, library.hasCandidate(Trigger.Op.ADD, Trigger.Type.BELIEF, beliefs.get(0)));
                library.hasCandidate(Trigger.Op.DEL, Trigger.Type.BELIEF, beliefs.get(6));
                library.hasCandidate(Trigger.Op.ADD, Trigger.Type.BELIEF, beliefs.get(8));
                library.remove("onP");
                assertEquals(false, library.hasCandidate(Trigger.Op.ADD, Trigger.Type.BELIEF, beliefs.get(0)));
            }
            for (int k = 0; k < 3; k++) {
                for (Literal b : beliefs) {
                    for (Trigger.Op op : List.of(Trigger.Op.DEL, Trigger.Op.ADD)) {
                        boolean byParts = library.hasCandidate(op, Trigger.Type.BELIEF, b);
                        assertEquals(!library.scan(new Trigger(op, Trigger.Type.BELIEF, b)).isEmpty(), byParts,
                                round + ": " + op + " " + b);
                        has += byParts ? 1 : 0;
                    }
                }
            }
        }
        // +p(1) and -q in rounds 0-3, +r(1) in rounds 2-5: three times a round
        assertEquals(3 * (2 + 2 + 3 + 3 + 2 + 2), has);
    }

    @Test
    void aGroupEmptiedAndFilledAgainKeepsTheOrderOfGroups() {
        assertEquals(List.of("[x(0),b(1),a(2)]", "[x(0),b(1),a(2),e(2),f(1)]"), run("""
                x(0).
                !g.
                +!g <- +a(1); -a(1); +b(1); +a(2);
                       .findall(B, B[source(self)], L3); .print(L3);
                       +e(1); -e(1); +e(2); +f(1);
                       .findall(B, B[source(self)], L4); .print(L4).
                """));
    }

    @Test
    void rangeGivesItsValuesInLoopsProofsAndBodies() {
        assertEquals(List.of("y3", "i5", "i3", "i1", "z1", "[2,4]", "11", "12", "21", "22", "11", "21", "22"), run("""
                !g.
                +!g <- Y = 3; for (.range(Y, 1, 5)) { .print(y, Y) };
                       for (.range(I, 5, 1, -2)) { .print(i, I) };
                       .range(Z, 1, 3); .print(z, Z);
                       .findall(V, .range(V, 1, 4) & V mod 2 == 0, L5); .print(L5);
                       for (.range(P, 1, 2)) { for (.range(Q, 1, 2)) { .print(P, Q) } };
                       +k(0); while (k(N) & N < 3) { for (.range(R, 1, N)) { .print(N, R) }; -+k(N + 1) }.
                """));
    }

    /** {@code PlanLibrary.CandidateKey}: the candidates cached for a predicate change with the library. */
    @Test
    void cachedCandidatePlansFollowPlansAddedAndRemoved() {
        assertEquals(List.of("base(1)", "extra(2)", "failed(h(3))"), run("""
                !g.
                +!g <- !h(1); +{ @extra +!h(X) : X > 1 <- .print(extra(X)) }; !h(2);
                       .remove_plan(extra); !h(3).
                +!h(X) : X < 2 <- .print(base(X)).
                -!h(X) <- .print(failed(h(X))).
                """));
    }

    /** {@code ReasoningCycle.firstArgsDiffer}: plans whose first argument is another constant are passed over unasked. */
    @Test
    void plansWithAnotherConstantFirstArgumentArePassedOver() {
        assertEquals(List.of("two", "any(3)", "b", "any(c)", "any(2.5)"), run("""
                !g.
                +!g <- !c(2); !c(3); !c(b); !c(c); !c(2.5).
                +!c(1) <- .print(one).
                +!c(2) <- .print(two).
                +!c(b) <- .print(b).
                +!c(X) <- .print(any(X)).
                """));
    }

    @Test
    void everyIntendedMeansOfAPlanStartsFromItsFirstStepListWhenPlansTakeTurns() {
        var a = new TestAgent("""
                +!a <- .print(a); .print(b).
                +!b <- .print(c).
                """);
        var start = new IntendedMeans.Start();
        var plans = a.agent.planLibrary().plans();
        Plan pa = plans.get(0);
        Plan pb = plans.get(1);
        var first = start.of(pa, pa.trigger(), new Unifier());
        var other = start.of(pb, pb.trigger(), new Unifier());
        var again = start.of(pa, pa.trigger(), new Unifier());
        assertSame(first.steps(), again.steps(), "plan a's steps, after plan b's");
        assertNotSame(first.steps(), other.steps());
        assertEquals(".print(a)", again.steps().head().toString());
        assertEquals(".print(b)", again.steps().next().head().toString());
        assertEquals(null, again.steps().next().next());
    }
}
