package jacabot.agent.parser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Var;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** How the parser places literals in namespaces, as Jason 3.2's parser does (its modules). */
class NamespaceParsingTest {
    private final AslParser parser = new AslParser();

    private static String plans(AgentProgram p) {
        return p.plans().stream().map(Object::toString).collect(Collectors.joining("\n"));
    }

    @Test
    void prefixesPrintAsWrittenAndDefaultIsNoNamespace() throws Exception {
        assertEquals("ns1::kk(30,j::uu)", parser.parseTerm("ns1::kk(30, j::uu)").toString());
        assertEquals("N::~p(1)[a]", parser.parseTerm("N::~p(1)[a]").toString());
        Literal d = (Literal) parser.parseTerm("default::b(1)");
        assertNull(d.ns());
        assertEquals(Literal.of("b", new NumberTerm(1)), d);
        assertTrue(((Literal) parser.parseTerm("NS::b")).ns() instanceof Var);
        // a variable with a namespace stands for a literal of that namespace
        var nsVar = (AnnotatedVar) parser.parseTerm("ns::X");
        assertEquals("ns::X", nsVar.toString());
        assertEquals(Literal.atom("ns"), nsVar.ns());
    }

    @Test
    void aBlockPutsFormulasInItsNamespaceButNotArgumentsKeywordsOrInternalActions() throws Exception {
        var p = parser.parse("""
                { begin namespace(ns1) }
                b1(t).
                +tick <- .print(t); !g(u); +b(tell)[source(self)]; X = ns1::a.
                +!ttt : bel(k, X)[a1] =.. [A, B, C, D] <- .print(A).
                { end }
                b5(i).
                """, "t.asl");
        assertEquals("ns1::b1(t)", p.beliefs().get(0).toString());
        assertEquals("b5(i)", p.beliefs().get(1).toString());
        String text = plans(p);
        assertTrue(text.contains("+ns1::tick <- .print(t); !ns1::g(u); +ns1::b(tell)[source(self)]; (X = a)"), text);
        assertTrue(text.contains("+!ns1::ttt : (bel(k,X)[a1] =.. [A,B,C,D]) <- .print(A)"), text);
    }

    @Test
    void localNamespacesGetUniqueNamesAndGlobalOnesKeepTheirs() throws Exception {
        var p = parser.parse("""
                { begin namespace(ns2, local) }
                b4(t).
                { end }
                { namespace(ns3, local) }
                b2(t) :- ns3::c & ns2::b4(t) & g::x.
                { begin namespace(g, global) } x. { end }
                """, "t.asl");
        String local = p.beliefs().get(0).toString();
        assertTrue(local.matches("#\\d+ns2::b4\\(t\\)"), local);
        String rule = p.beliefs().get(1).toString();
        assertTrue(rule.matches("b2\\(t\\) :- \\(#\\d+ns3::c & \\(#\\d+ns2::b4\\(t\\) & g::x\\)\\)"), rule);
        assertEquals("g::x", p.beliefs().get(2).toString());
    }

    @Test
    void anIncludedModuleIsReadInItsNamespaceAndThisNsNamesIt(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("m.asl"), """
                { namespace(priv, local) }
                priv::n(0).
                +!go <- .print(this_ns); ?priv::n(X); .send(bob, tell, ::done(X)).
                """);
        Files.writeString(dir.resolve("main.asl"), """
                { include("m.asl", a) }
                { include("m.asl", b) }
                { include("m.asl") }
                """);
        var p = new AslParser(List.of(dir)).parseFile(dir.resolve("main.asl"));
        String text = plans(p);
        assertTrue(text.contains("+!a::go <- .print(a); ?#1priv::n(X); .send(bob,tell,a::done(X))"), text);
        assertTrue(text.contains("+!b::go <- .print(b); ?#2priv::n(X); .send(bob,tell,b::done(X))"), text);
        assertTrue(text.contains("+!go <- .print(default); ?#3priv::n(X); .send(bob,tell,done(X))"), text);
        assertEquals("[#1priv::n(0), #2priv::n(0), #3priv::n(0)]", p.beliefs().toString());
    }

    @Test
    void aPlanAddedInABodyBecomesAddPlan() throws Exception {
        var p = parser.parse("+!g(T) <- +{ +T::winner(W) <- .print(W) }; +>{ +b <- x }; -{ +b <- x }.", "t.asl");
        assertEquals(".add_plan({ +T::winner(W) <- .print(W) },self,begin); .add_plan({ +b <- x },self,end); .remove_plan({ +b <- x })",
                p.plans().get(0).body().bodyText());
    }

    @Test
    void badNamespaceDirectivesAreReported() {
        var e = assertThrows(AslSyntaxException.class, () -> parser.parse("{ namespace(n, private) }\n", "bad.asl"));
        assertTrue(e.getMessage().startsWith("bad.asl:1:1: error: the second argument of the namespace directive"), e.getMessage());
        var v = assertThrows(AslSyntaxException.class, () -> parser.parse("{ begin namespace(N) }\n{ end }\n", "v.asl"));
        assertTrue(v.getMessage().startsWith("v.asl:1:1: error: the namespace directive needs an atom"), v.getMessage());
    }
}
