package jacabot.agent.stdlib;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import jacabot.agent.testing.TestAgent;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * What the Jason oracle programs cannot show: a seeded .shuffle, errors Jason gives as Java
 * exceptions, and .list_rules (Jason also lists its KQML rules, in an order of its hash map).
 */
class StringsAndTermsTest {
    private static List<String> run(String program) {
        var a = new TestAgent(program);
        a.cycles(50);
        return a.printed();
    }

    @Test
    void shuffleFollowsTheSeedOfSetRandomSeed() {
        String program = """
                !g.
                +!g <- .set_random_seed(%d); .shuffle([a,b,c,d,e,f,g,h], L); .print(L).
                """;
        List<String> first = run(program.formatted(42));
        assertEquals(first, run(program.formatted(42)));
        assertNotEquals(first, run(program.formatted(7)), "another seed, another order");
        assertNotEquals(List.of("[a,b,c,d,e,f,g,h]"), first);
    }

    @Test
    void replaceOfANonStringOrBadExpressionFailsWithUnknownAndSaysWhy() {
        assertEquals(List.of("unknown Wrong argument for internal action 'replace': 'banana' is not a string",
                "unknown Error in internal action 'replace': Unclosed group near index 1"), run("""
                !g(banana, "a"). !g("abc", "(").
                +!g(S, P) <- .replace(S, P, "o", _).
                -!g(_, _)[error(E), error_msg(M)] <- .print(E, " ", M).
                """));
    }

    @Test
    void copyTermOfANumberOrStringFailsWithUnknown() {
        assertEquals(List.of("unknown", "unknown", "f(_,_)"), run("""
                !g(1). !g("s"). !h.
                +!g(T) <- .copy_term(T, _).
                -!g(_)[error(E)] <- .print(E).
                +!h <- .copy_term(f(X, X), f(A, B)); A = 1; if (B == 1) { .print("f(_,_)") }.
                """));
    }

    @Test
    void putsPrintsTheValueOfAVariableBoundInTheSamePlan() {
        assertEquals(List.of("n=3 s=x l=[1,\"a\"]"), run("""
                !g.
                +!g <- N = 3; S = "x"; L = [1, "a"]; .puts("n=#{N} s=#{S} l=#{L}").
                """));
    }

    @Test
    void listRulesPrintsEachRuleAndNoFact() {
        List<String> printed = run("""
                r(X) :- X > 1 & b(X).
                r(1) :- true.
                b(3).
                !g.
                +!g <- .list_rules(ignored).
                """);
        assertEquals(List.of("r(X)[source(self)] :- ((X > 1) & b(X))", "r(1)[source(self)] :- true"), printed);
    }
}
