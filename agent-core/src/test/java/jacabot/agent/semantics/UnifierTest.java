package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import org.junit.jupiter.api.Test;

class UnifierTest {
    private final AslParser parser = new AslParser();

    private Term t(String text) throws Exception {
        return parser.parseTerm(text);
    }

    @Test
    void bindsVariablesOnBothSides() throws Exception {
        var u = new Unifier();
        assertTrue(u.unifies(t("f(X, b, [1|T])"), t("f(a, Y, [1,2,3])")));
        assertEquals("a", u.apply(new Var("X")).toString());
        assertEquals("b", u.apply(new Var("Y")).toString());
        assertEquals("[2,3]", u.apply(new Var("T")).toString());
    }

    @Test
    void sharedVariablesMustAgree() throws Exception {
        var u = new Unifier();
        assertFalse(u.unifies(t("g(X, X)"), t("g(1, 2)")));
        assertTrue(u.isEmpty(), "a failed unification leaves no binding behind");
        assertTrue(u.unifies(t("g(X, X)"), t("g(1, 1.0)")), "1 and 1.0 are the same number");
    }

    @Test
    void annotationsOfTheFirstTermMustBeASubset() throws Exception {
        assertTrue(new Unifier().unifies(t("p(1)[a]"), t("p(1)[a,b]")));
        assertFalse(new Unifier().unifies(t("p(1)[a,b]"), t("p(1)[a]")));
        var u = new Unifier();
        assertTrue(u.unifies(t("p[source(S)]"), t("p[x,source(bob)]")));
        assertEquals("bob", u.apply(new Var("S")).toString());
    }

    @Test
    void aTailInALiteralsAnnotationsTakesTheOthers() throws Exception {
        var u = new Unifier();
        assertTrue(u.unifies(t("b(1)[x|A]"), t("b(1)[source(self),x,y]")));
        assertEquals("[source(self),y]", u.apply(new Var("A")).toString());
        u = new Unifier();
        assertTrue(u.unifies(t("d[a,b]"), t("d[a|T]")), "what the first has beyond the second's goes to its tail");
        assertEquals("[b]", u.apply(new Var("T")).toString());
        u = new Unifier();
        // as Jason: d[a|T] = d[b|U] gives U = [a] and T = [b|U]
        assertTrue(u.unifies(t("d[a|T]"), t("d[b|U]")));
        assertEquals("[a]", u.apply(new Var("U")).toString());
        assertEquals("[b,a]", u.apply(new Var("T")).toString());
        u = new Unifier();
        assertTrue(u.unifies(t("d[a|T]"), t("d[a|U]")));
        assertEquals("[]", u.apply(new Var("T")).toString());
        assertFalse(new Unifier().unifies(t("d[a|T]"), t("d[b,c]")));
        assertFalse(new Unifier().unifies(t("d[|T]"), t("d")), "as Jason, a tail alone needs some annotation");
        assertTrue(new Unifier().unifies(t("d"), t("d[|T]")));
    }

    @Test
    void aBoundTailBringsItsElementsIntoTheAnnotations() throws Exception {
        var u = new Unifier();
        assertTrue(u.unifies(new Var("T"), t("[y,w]")));
        Term applied = u.apply(t("d(1)[x|T]"));
        assertEquals("d(1)[w,x,y]", applied.toString());
        assertTrue(applied.isGround());
        assertEquals(t("d(1)[w,x,y]"), applied);
        u = new Unifier();
        assertTrue(u.unifies(new Var("T"), t("[y|R]")));
        assertEquals("d[x,y|R]", u.apply(t("d[x|T]")).toString());
        u = new Unifier();
        assertTrue(u.unifies(new Var("T"), t("[y]")));
        assertTrue(u.unifies(t("d[x|T]"), t("d[x,y,z]")), "the bound tail's elements are matched too");
        assertFalse(u.unifies(t("d[x|T]"), t("d[x,z]")));
    }

    @Test
    void aLiteralWithATailPrintsAndComparesAsJasons() throws Exception {
        assertEquals("c[|T]", t("c[|T]").toString());
        assertEquals("c(1)[a,b|T]", t("c(1)[b,a|T]").toString());
        assertEquals("c[z]", t("c[z|[]]").toString(), "an empty tail is none");
        assertEquals(t("c[|T]"), t("c[|T]"));
        assertEquals(t("c[|T]").hashCode(), t("c[|T]").hashCode());
        assertFalse(t("c[|T]").equals(t("c")));
        assertFalse(t("c[a|T]").equals(t("c[a|U]")));
        assertFalse(t("c[|T]").isGround());
        assertTrue(t("c").compareTo(t("c[|T]")) < 0);
        assertTrue(t("c[|T]").compareTo(t("c[a]")) < 0);
        assertTrue(t("c[a]").compareTo(t("c[a|T]")) < 0);
    }

    @Test
    void stringsAtomsAndStructuresAreDistinct() throws Exception {
        assertFalse(new Unifier().unifies(t("\"a\""), t("a")));
        assertFalse(new Unifier().unifies(t("f(x)"), t("g(x)")));
        assertFalse(new Unifier().unifies(t("f(x, y)"), t("f(x)")));
        assertFalse(new Unifier().unifies(t("~p"), t("p")));
    }

    @Test
    void arithmeticIsEvaluatedOnceBound() throws Exception {
        var u = new Unifier();
        assertTrue(u.unifies(new Var("X"), t("3")));
        assertEquals("7", u.apply(t("X * 2 + 1")).toString());
        assertEquals("(Y+1)", u.apply(t("Y + 1")).toString(), "unbound operands keep the expression");
        assertTrue(u.unifies(t("X + 1"), t("4")));
    }

    @Test
    void copiesAreIndependent() throws Exception {
        var u = new Unifier();
        u.unifies(new Var("X"), t("1"));
        var c = u.copy();
        c.unifies(new Var("Y"), t("2"));
        assertEquals("Y", u.apply(new Var("Y")).toString());
        assertEquals("2", c.apply(new Var("Y")).toString());
    }

    /** {@code Substitution}'s shortcut: a term with no bound variable comes back as it is, not copied. */
    @Test
    void applyingToATermWithNothingBoundGivesTheSameTerm() throws Exception {
        var u = new Unifier();
        u.unifies(new Var("X"), t("1"));
        Term free = t("p(Y, [a, Z], q(W)[n])");
        assertSame(free, u.apply(free));
        Term bound = t("p(X, [a, X], q(W)[n])");
        assertEquals("p(1,[a,1],q(W)[n])", u.apply(bound).toString());
    }
}
