package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TermOrder;
import jacabot.agent.syntax.Var;
import jacabot.agent.testing.TestAgent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Namespaces in unification, order, the belief base and the plan library, as in Jason 3.2. */
class NamespaceTest {
    private final AslParser parser = new AslParser();

    private Term t(String text) throws Exception {
        return parser.parseTerm(text);
    }

    @Test
    void literalsUnifyOnlyInTheSameNamespaceAndAVariableNamespaceTakesIt() throws Exception {
        assertTrue(new Unifier().unifies(t("ns1::kk(30, j::uu)"), t("ns1::kk(30, j::uu)")));
        assertFalse(new Unifier().unifies(t("ns1::kk(30, j::uu)"), t("ns1::kk(30, uu)")));
        assertFalse(new Unifier().unifies(t("ns1::kk(30, j::uu)"), t("ns2::kk(30, j::uu)")));
        assertFalse(new Unifier().unifies(t("ns1::kk(30)"), t("kk(30)")));
        assertTrue(new Unifier().unifies(t("default::kk(30)"), t("kk(30)")));
        var u = new Unifier();
        assertTrue(u.unifies(t("A::kk(30, j::uu(X))"), t("ns1::kk(30, j::uu(uu))")));
        assertEquals("ns1", u.apply(new Var("A")).toString());
        assertEquals("uu", u.apply(new Var("X")).toString());
        assertEquals("ns1::kk(1)", u.apply(t("A::kk(1)")).toString());
        var d = new Unifier();
        assertTrue(d.unifies(t("A::b"), t("b")));
        assertEquals("default", d.apply(new Var("A")).toString());
        assertEquals("b", d.apply(t("A::b")).toString(), "a namespace bound to default prints no prefix");
    }

    @Test
    void aPlainVariableTakesNoLiteralOfANamespaceNorALocalName() throws Exception {
        assertFalse(new Unifier().unifies(new Var("X"), t("ns::bob(45)")));
        assertTrue(new Unifier().unifies(new Var("X"), t("bob(45)")));
        assertFalse(new Unifier().unifies(t("A::bob"), Literal.atom("bob").withNs(Literal.atom("#1ns"))));
        assertTrue(new Unifier().unifies(new Var("X"), t("10")));
    }

    @Test
    void aVariableWithANamespaceTakesTheLiteralInTheDefaultNamespace() throws Exception {
        var u = new Unifier();
        assertTrue(u.unifies(t("ns::A"), t("ns::bob[x]")));
        assertEquals("bob[x]", u.apply(new Var("A")).toString());
        assertEquals("ns::bob[x]", u.apply(t("ns::A")).toString());
        assertFalse(new Unifier().unifies(t("ns::A"), t("xx::bob")));
        assertFalse(new Unifier().unifies(t("ns::A"), t("bob")));
        var both = new Unifier();
        assertTrue(both.unifies(t("ns::A"), t("B::bob")));
        assertEquals("bob", both.apply(new Var("A")).toString());
        assertEquals("ns", both.apply(new Var("B")).toString());
        assertFalse(new Unifier().unifies(new Var("X"), t("ns::Y")), "X and ns::Y are in different namespaces");
        var n = new Unifier();
        assertTrue(n.unifies(t("ns::A"), t("10")), "numbers have no namespace");
        assertEquals("10", n.apply(new Var("A")).toString());
        var k = new Unifier();
        assertTrue(k.unifies(t("kk(30, j::X)"), t("kk(30, j::uu)")));
        assertEquals("uu", k.apply(new Var("X")).toString());
    }

    @Test
    void namespacesComeFirstInTheStandardOrder() throws Exception {
        assertTrue(TermOrder.compare(t("ns1::b"), t("ns2::a")) < 0);
        assertTrue(TermOrder.compare(t("ns2::a"), t("ns1::b")) > 0);
        assertTrue(TermOrder.compare(t("ns1::a"), t("ns1::b")) < 0);
        assertTrue(TermOrder.compare(t("a"), t("ns::a")) < 0, "default < ns");
        assertFalse(t("ns1::a").equals(t("ns2::a")));
        assertEquals(t("default::a"), t("a"));
    }

    @Test
    void beliefsQueriesAndEventsKeepTheirNamespaces() {
        var a = new TestAgent("ns", """
                b(0).
                ns2::b(2).
                !g.
                +!g <- +ns3::c(1); .findall(N::b(X), N::b(X), L); .print(L);
                       .findall(N, .namespace(N), NL); .print(NL);
                       ?ns2::b(Y); .print(Y);
                       -ns2::b(2); .count(_::b(_), K); .print(K);
                       !!ns3::h.
                +ns3::c(X) <- .print(c(X)).
                +!N::h <- .print(h_in(N)).
                """);
        a.cycles(60);
        // .namespace lists them in Jason's order (its belief base's hash map), kqml included
        assertEquals(List.of("c(1)", "[b(0),ns2::b(2)]", "[kqml,default,ns3,ns2]", "2", "1", "h_in(ns3)"), a.printed());
    }

    @Test
    void aModuleIncludedAtRunTimeGetsItsNamespace(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("m.asl"), """
                n(1).
                +!go : n(X) <- .print(in(this_ns, X)); +::done.
                """);
        Files.writeString(dir.resolve("main.asl"), """
                !start.
                +!start <- .include("m.asl", x); !x::go; .include("m.asl", V); !V::go; .print(V).
                +x::done <- .print(x_done).
                """);
        var a = TestAgent.fromFile("main", dir.resolve("main.asl"));
        a.cycles(80);
        assertEquals(List.of("in(x,1)", "x_done", "in(ns1,1)", "ns1"), a.printed());
    }
}
