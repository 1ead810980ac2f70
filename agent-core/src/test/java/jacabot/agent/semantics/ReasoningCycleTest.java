package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.testing.TestAgent;
import java.util.List;
import org.junit.jupiter.api.Test;

class ReasoningCycleTest {

    @Test
    void firstApplicablePlanInFileOrderWithTheFirstUnifier() {
        var a = new TestAgent("""
                v(1). v(2). v(3).
                !g.
                +!g : v(X) & X > 1 <- .print(first, X).
                +!g <- .print(second).
                """);
        a.cycles(20);
        assertEquals(List.of("first2"), a.printed());
    }

    @Test
    void runawayGoalRecursionFailsTheGoalAtTheIntentionDepthLimit() {
        // not a tail call: each !g stays under the plan that posted it, and the intention grows
        var a = new TestAgent("""
                !start.
                +!start <- !g(0).
                +!g(N) <- !g(N + 1); .print(never).
                -!start[error(E)] <- .print(E).
                """);
        a.cycles(4 * ReasoningCycle.MAX_INTENTION_DEPTH);
        assertEquals(List.of("stack_overflow"), a.printed());
    }

    @Test
    void failureAnnotationsTellWhatFailedAndWhere() {
        var a = new TestAgent("""
                !g.
                +!g <- X = 1;
                       X > 2.
                -!g[error(E), code(C), code_line(L), error_msg(M)] <- .print(E, " ", C, " ", L).
                """);
        a.cycles(20);
        assertEquals(List.of("constraint_failed (1 > 2) 3"), a.printed());
    }

    @Test
    void unhandledFailureWarnsInJasonsWordsAndDropsTheIntention() {
        var a = new TestAgent("""
                !g.
                +!g <- .fail; .print(never).
                """);
        a.cycles(20);
        assertTrue(a.printed().get(0).startsWith("No failure event was generated for +!g["), a.printed().toString());
        assertFalse(a.printed().contains("never"));
        assertTrue(a.agent.canSleep());
    }

    @Test
    void aGoalWhosePlansAllFailToUnifyHasNoApplicablePlanAsInJason() {
        // Jason 3.2.0 prints "m no_applicable" and "n no_applicable": a plan of the goal's functor
        // and arity exists, even one its arguments or annotations do not match
        var a = new TestAgent("""
                !g.
                +!g <- !m(1); !n[a].
                +!m(2) <- .print(x).
                +!n[b] <- .print(y).
                -!m(_)[error(E)] <- .print(m, " ", E).
                -!n[error(E)] <- .print(n, " ", E).
                """);
        a.cycles(30);
        assertEquals(List.of("m no_applicable", "n no_applicable"), a.printed());
    }

    @Test
    void aFailureEventNoPlanAppliesToWarnsAsJasonDoes() {
        var a = new TestAgent("""
                !top.
                +!top <- !g; .print(never).
                +!g <- .fail.
                -!g[foo] <- .print(no).
                """);
        a.cycles(30);
        // recorded from Jason 3.2.0: the intention's dump, then why the failure event found no plan
        assertEquals(2, a.printed().size(), a.printed().toString());
        assertTrue(a.printed().get(0).startsWith("Could not finish intention:\nintention 1: \n    +!g[source(self)] <- ... .fail / {}\n"),
                a.printed().get(0));
        assertTrue(a.printed().get(1).startsWith("Found a goal for which there is no applicable plan: -!g[code(.fail)"),
                a.printed().get(1));
    }

    @Test
    void aFailGoalOfItsOwnGoalWithNoApplicableFailurePlanGoesOnAsInJason() {
        // Jason 3.2.0: the two warnings, then "after_g": the intention that ran .fail_goal stays
        // in I and goes on past the step that posted the failed goal
        var a = new TestAgent("""
                !top.
                +!top <- !g; .print(after_g).
                +!g <- !h; .print(never).
                +!h <- .fail_goal(g); .print(never).
                -!g[foo] <- .print(never).
                """);
        a.cycles(30);
        assertEquals(3, a.printed().size(), a.printed().toString());
        assertTrue(a.printed().get(0).startsWith("Could not finish intention:\nintention 1: \n    +!top[source(self)] <- ... .print(after_g) / {}"),
                a.printed().get(0));
        assertEquals("Found a goal for which there is no applicable plan: -!g", a.printed().get(1));
        assertEquals("after_g", a.printed().get(2));
    }

    @Test
    void theUnhandledFailureWarningShowsTheIntentionAsJasonPrintsIt() {
        var a = new TestAgent("""
                !top.
                +!top <- X = 1; !g(X); .print(never).
                +!g(N) <- Y = N + 1; .fail; .print(never).
                """);
        a.cycles(20);
        String[] lines = a.printed().get(0).split("\n", -1);
        // recorded from Jason 3.2.0: a line per intended means, top first, what is left of its body and its
        // unifier in the order of Jason's hash map
        assertEquals("intention 1: ", lines[1]);
        assertEquals("    +!g(1)[source(self)] <- ... .fail; .print(never) / {Y=2, N=1}", lines[2]);
        assertEquals("    +!top[source(self)] <- ... !g(X); .print(never) / {X=1}", lines[3]);
        assertEquals("", lines[4]);
    }

    @Test
    void environmentActionsWaitForFeedbackAndFailWithActionFailed() {
        var a = new TestAgent("""
                !g.
                +!g <- move(1); move(2); .print(done).
                -!g[error(E)] <- .print(E).
                """);
        a.environment = act -> !act.action().toString().equals("move(2)");
        a.cycles(30);
        assertEquals(List.of("move(1)", "move(2)"), a.actionNames());
        assertEquals(List.of("action_failed"), a.printed());
    }

    @Test
    void tailRecursionKeepsTheIntentionStackFlat() {
        var a = new TestAgent("""
                !count(0).
                +!count(N) : N < 5000 <- !count(N + 1).
                +!count(N) <- .print(N).
                """);
        int maxDepth = 0;
        for (int i = 0; i < 20000 && a.printed().isEmpty(); i++) {
            a.agent.reasoningCycle();
            for (Intention in : a.agent.circumstance().allIntentions()) {
                maxDepth = Math.max(maxDepth, in.size());
            }
        }
        assertEquals(List.of("5000"), a.printed());
        assertTrue(maxDepth <= 2, "stack depth " + maxDepth);
    }

    @Test
    void resultsOfSubgoalsFlowBackThroughRecursion() {
        var a = new TestAgent("""
                !start.
                +!start <- !fact(10, F); .print(F).
                +!fact(0, 1).
                +!fact(N, F) <- !fact(N - 1, F1); F = N * F1.
                """);
        a.cycles(200);
        assertEquals(List.of("3628800"), a.printed());
    }

    @Test
    void atomicIntentionRunsAlone() {
        var a = new TestAgent("""
                !a. !b.
                +!a <- .print(a1); .print(a2); .print(a3).
                @x[atomic] +!b <- .print(b1); .print(b2); .print(b3).
                """);
        a.cycles(50);
        assertEquals(List.of("a1", "b1", "b2", "b3", "a2", "a3"), a.printed());
    }

    /** Jason keeps an atomic intention that waits for its action's feedback as the one to run next. */
    @Test
    void atomicIntentionWaitingForItsActionStillRunsAlone() {
        var a = new TestAgent("""
                !a. !b.
                +!a <- .print(a1); .print(a2).
                @x[atomic] +!b <- .print(b1); move; .print(b2).
                +seen <- .print(c1).
                """);
        a.deferFeedback = true;
        a.cycles(50);
        a.percepts = List.of(Literal.atom("seen"));
        a.cycles(50);
        assertEquals(List.of("a1", "b1"), a.printed());
        a.finishActions().cycles(50);
        assertEquals(List.of("a1", "b1", "b2", "a2", "c1"), a.printed());
    }

    /** An atomic plan's failed action goes to its failure plan once, as Jason's (it was run again every cycle). */
    @Test
    void atomicIntentionWhoseActionFailsRunsItsFailurePlanOnce() {
        var a = new TestAgent("""
                !a. !b.
                +!a <- .print(a1); .print(a2).
                @x[atomic] +!b <- .print(b1); release(5); .print(never).
                -!b[error(E)] <- .print(E).
                """);
        a.environment = act -> !act.action().toString().equals("release(5)");
        a.cycles(200);
        assertEquals(List.of("release(5)"), a.actionNames());
        // the failure event waits for the next cycle's SelEv; the other intention runs meanwhile (Jason's order)
        assertEquals(List.of("a1", "b1", "a2", "action_failed"), a.printed());
    }

    @Test
    void perceptsBecomeBeliefsWithSourcePerceptAndEvents() {
        var a = new TestAgent("""
                +obstacle(D)[source(percept)] <- .print(seen, D).
                -obstacle(D) <- .print(gone, D).
                """);
        a.percepts = List.of(Literal.of("obstacle", new NumberTerm(350)));
        a.cycles(10);
        assertTrue(a.believes("obstacle(350)[source(percept)]"));
        a.percepts = List.of();
        a.cycles(10);
        assertFalse(a.believes("obstacle(_)"));
        assertEquals(List.of("seen350", "gone350"), a.printed());
    }
}
