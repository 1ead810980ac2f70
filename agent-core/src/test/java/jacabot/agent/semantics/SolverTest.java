package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import jacabot.agent.testing.TestAgent;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

class SolverTest {
    private static final String ANCESTOR = """
            ancestor(X, Y) :- parent(X, Y).
            ancestor(X, Y) :- parent(X, Z) & ancestor(Z, Y).
            """;

    @Test
    void solutionsComeInJasonsOrderThroughRulesDisjunctionsNegationAndActions() {
        // each line as Jason 3.2.0 prints it for the same program
        var a = new TestAgent("""
                b(1). b(2)[x]. b(3)[x, y].
                c(a). c(b).
                r(X) :- b(X) | c(X).
                r(z).
                s(X, Y) :- r(X) & .member(Y, [p, q]) & not (X == 2).
                t(X)[h] :- b(X)[x].
                u(X) :- X = 1 | X = 2 | b(X).
                d(X) :- e(X).
                e(1). e(X) :- X = f(Y) & Y = 3.
                !go.
                +!go <- .findall(X, r(X), L1); .print(L1);
                        .findall(p(X, Y), s(X, Y), L2); .print(L2);
                        .findall(X, t(X)[h], L3); .print(L3);
                        .findall(X, u(X), L4); .print(L4);
                        .count(r(_), C); .print(C);
                        .findall(A, b(3)[A], L6); .print(L6);
                        .findall(X, d(X), L7); .print(L7);
                        .findall(X, (b(X) & X > 1) | c(X), L8); .print(L8);
                        for (r(Q)) { .print(Q) }.
                """);
        a.cycles(200);
        assertEquals(List.of("[1,2,3,a,b,z]", "[p(1,p),p(1,q),p(3,p),p(3,q),p(a,p),p(a,q),p(b,p),p(b,q),p(z,p),p(z,q)]",
                "[2,3]", "[1,2,1,2,3]", "6", "[source(self),x,y]", "[1,f(3)]", "[2,3,a,b]", "1", "2", "3", "a", "b", "z"),
                a.printed());
    }

    @Test
    void aRuleBodyRenamedGoalByGoalLeavesAGoalBoundAtRunTimeAsItIs() {
        // t's body is its variable G: the conjunction G is bound to comes from the query, and its Y is the
        // query's, not the rule's Y (bound to 5); backtracking into b gives c(Y) the next b anew
        var a = new TestAgent("""
                b(1). b(2). c(2). c(3).
                t(G, Y) :- G.
                w(X) :- (b(X) | X = 3) & c(X) & not b(3).
                !go.
                +!go <- .findall(Y, t((b(Y) & c(Y)), 5), L1); .print(L1);
                        .findall(X, w(X), L2); .print(L2).
                """);
        a.cycles(50);
        assertEquals(List.of("[2]", "[2,3]"), a.printed());
    }

    @Test
    void aProofDeeperThanJavasStackSucceeds() {
        // 20 000 nested rules: the old recursive solver ran out of Java stack long before
        var a = new TestAgent(ANCESTOR + """
                !go.
                +!go <- for (.range(I, 1, 20000)) { +parent(I, I + 1) };
                        ?ancestor(1, 20001); .print(yes);
                        .findall(Y, ancestor(19990, Y), L); .print(L).
                -!go[error(E)] <- .print(E).
                """);
        a.cycles(100_000);
        assertEquals(List.of("yes", "[19991,19992,19993,19994,19995,19996,19997,19998,19999,20000,20001]"), a.printed());
    }

    @Test
    void runawayRuleRecursionFailsTheGoalWithStackOverflow() {
        var a = new TestAgent("""
                p(X) :- p(f(X)).
                q :- q.
                !g1. !g2.
                +!g1 <- ?p(1); .print(never).
                +!g2 <- ?q; .print(never).
                -!g1[error(E)] <- .print(g1, E).
                -!g2[error(E)] <- .print(g2, E).
                """);
        a.cycles(50);
        assertEquals(Set.of("g1stack_overflow", "g2stack_overflow"), Set.copyOf(a.printed()));
    }

    @Test
    void aSolutionBindsTheFormulasVariablesNotTheRulesOwn() throws Exception {
        var a = new TestAgent(ANCESTOR + "parent(1, 2). parent(2, 3). parent(3, 4).");
        a.cycles(5);
        var it = a.agent.solver().solve(new AslParser().parseTerm("ancestor(1, Y)"), new Unifier());
        var found = new ArrayList<String>();
        while (it.hasNext()) {
            Unifier u = it.next();
            assertEquals(Set.of(new Var("Y")), u.bindings().keySet());
            found.add(u.get(new Var("Y")).toString());
        }
        assertEquals(List.of("2", "3", "4"), found);
        Unifier u = new Unifier();
        assertTrue(a.agent.solver().believes(new AslParser().parseTerm("ancestor(2, Y)"), u));
        assertEquals(Set.of(new Var("Y")), u.bindings().keySet());
        assertFalse(a.agent.solver().believes(new AslParser().parseTerm("ancestor(4, Y)"), u = new Unifier()));
        assertTrue(u.isEmpty());
    }

    @Test
    void aLoopsAnswersPrintTheSameEveryTimeSoACapturedIntentionIsStable() throws Exception {
        var a = new TestAgent(ANCESTOR + "parent(1, 2).");
        a.cycles(5);
        Term formula = new AslParser().parseTerm("ancestor(1, Y)");
        String one = new ObjectTerm(a.agent.solver().solve(formula, new Unifier())).toString();
        String other = new ObjectTerm(a.agent.solver().solve(formula, new Unifier())).toString();
        assertEquals(one, other);
        assertFalse(one.contains("@"), one);
    }

    @Test
    void queriesByFirstArgumentKeepBeliefBaseOrderAsTheGroupChanges() {
        // a group large enough to be indexed, with entries that do not name a first argument among the facts
        var a = new TestAgent("""
                m(X, any).
                m(5, rule) :- true.
                m(X, var) :- X > 3.
                !go.
                +!go <- for (.range(I, 1, 40)) { +>m(I, I * 10) };
                        +>m(5, last); +m(5, first);
                        for (.range(K, 1, 6)) { .findall(V, m(5, V), L); .print(L) };
                        .findall(V, m(7, V), L7); .print(L7);
                        .findall(V, m(2, V), L2); .print(L2);
                        .findall(V, m("5", V), Ls); .print(Ls);
                        -m(5, 50); +>m(5, again);
                        .findall(V, m(5, V), M); .print(M).
                """);
        a.cycles(500);
        String five = "[first,any,rule,var,50,last]";
        assertEquals(List.of(five, five, five, five, five, five, "[any,var,70]", "[any,20]", "[any,var]",
                "[first,any,rule,var,last,again]"), a.printed());
    }
}
