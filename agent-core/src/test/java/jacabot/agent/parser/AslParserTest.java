package jacabot.agent.parser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AslParserTest {
    private final AslParser parser = new AslParser();

    @Test
    void readsPlansWithLabelsContextsAndEveryKindOfBodyFormula() throws Exception {
        var program = parser.parse("""
                @p1[atomic] +!g(X) : b(X) & not c | X > 1 <- !a; !!b; ?c; +d; +>e; -f; -+h(1); --i; ++j; act(X); .print(X); Y = X + 1.
                """, "t.asl");
        Plan p = program.plans().get(0);
        assertEquals("p1", p.label().functor());
        assertTrue(p.isAtomic());
        assertEquals("+!g(X)", p.trigger().toString());
        assertEquals("((b(X) & not (c)) | (X > 1))", p.context().toString());
        assertEquals("!a; !!b; ?c; +d; +>e; -f; -+h(1); --i; ++j; act(X); .print(X); (Y = (X+1))", p.body().bodyText());
        assertEquals(BodyStep.Kind.INTERNAL_ACTION, p.body().steps().get(10).kind());
        assertEquals(BodyStep.Kind.CONSTRAINT, p.body().steps().get(11).kind());
    }

    @Test
    void readsBeliefsRulesGoalsAndTerms() throws Exception {
        var program = parser.parse("""
                ~p(1.5e3, "s\\"q", 'Quoted atom', [a, b | T], f(_))[x].
                r(X) :- p(X) & X > 2.
                !start.
                """, "t.asl");
        assertEquals("~p(1500,\"s\"q\",'Quoted atom',[a,b|T],f(_1))[x]",
                program.beliefs().get(0).toString().replaceAll("_[0-9]+", "_1"));
        assertEquals("r(X) :- (p(X) & (X > 2))", program.beliefs().get(1).toString());
        assertEquals(Literal.atom("start"), program.goals().get(0));
    }

    @Test
    void controlStructuresBecomeJasonsInternalActions() throws Exception {
        var program = parser.parse("""
                +!g <- if (a) { b } elif (c) { d } else { e }; while (x) { y } for (z(I)) { w(I) }.
                """, "t.asl");
        // Jason 3.2.0 prints the bodies a statement makes bare
        assertEquals(".if_then_else(a,b,.if_then_else(c,d,e)); .loop(x,y); .foreach(z(I),w(I))",
                program.plans().get(0).body().bodyText());
    }

    @Test
    void bracedBodiesWrittenAsFormulasAreFlattenedAsInJason() throws Exception {
        // Jason 3.2.0 runs and prints this plan as a; b; c; .fork(or,x,y; z); .fork(and,d,e)
        var program = parser.parse("""
                +!g <- { a; b }; c; x ||| { y; z }; { d } |&| e; {}.
                +!h <- .print({ { a }; if (t) { } }, { b }).
                """, "t.asl");
        assertEquals("a; b; c; .fork(or,x,y; z); .fork(and,d,e)", program.plans().get(0).body().bodyText());
        assertEquals(".print({ a; .if_then_else(t,) },{ b })", program.plans().get(1).body().bodyText());
    }

    @Test
    void aMinusBeforeWhatIsNoNumberIsAnErrorAsInJason() throws Exception {
        // Jason 3.2.0 refuses -p, -f(x), -(a) and -(X > 1) as it reads the file, and takes -X,
        // -(1+2) and -math.abs(-3)
        for (String t : List.of("-p", "-f(x)", "-(a)", "-(X > 1)")) {
            var e = assertThrows(AslSyntaxException.class, () -> parser.parse("+!g <- .print(" + t + ").\n", "m.asl"), t);
            assertTrue(e.getMessage().contains("of operator '-' is not numeric or variable"), e.getMessage());
        }
        parser.parse("+!g <- .print(-X, -(1+2), -math.abs(-3), - 3).\n", "m.asl");
    }

    @Test
    void aBeliefUpdateFollowedByAnotherWithoutASemicolonIsOneErrorAsInJason() throws Exception {
        // Jason 3.2.0 reads `+a(1) -b` as the arithmetic a(1)-b and refuses it at its first operand
        // ("ArithExpr: first operand 'a(1)' is not numeric or variable"): one line, no consequences
        // of it (the second operand, the operand of '+'), and the likely cause named
        for (String body : List.of("+a(1) -b", "+a -b(2)", ".print(1) -b", "-a(1) +b")) {
            var e = assertThrows(AslSyntaxException.class, () -> parser.parse("+!g <- " + body + ".\n", "m.asl"), body);
            String first = body.replaceAll("^[+-]", "").replaceAll(" [+-].*", "");
            assertEquals(1, e.getMessage().strip().lines().count(), e.getMessage());
            assertTrue(e.getMessage().contains("error: ArithExpr: first operand '" + first + "' is not numeric or variable"
                    + " (a ';' missing before '" + body.substring(body.indexOf(' ') + 1) + "'?)"), e.getMessage());
        }
        var e = assertThrows(AslSyntaxException.class, () -> parser.parse("+!g <- +X -b.\n", "m.asl"));
        assertEquals("m.asl:1:9: error: ArithExpr: second operand 'b' is not numeric or variable (a ';' missing before '-b'?)",
                e.getMessage().strip());
    }

    @Test
    void anOperandThatIsNoNumberIsAnErrorAsInJason() throws Exception {
        // Jason 3.2.0's messages, the grammar rule of the operator named
        var cases = Map.of("1 + a", "ArithExpr: second operand 'a' is not numeric or variable",
                "f(1) * 2", "ArithTerm: first operand 'f(1)' is not numeric or variable",
                "a ** 2", "ArithFactor: first operand 'a' is not numeric or variable",
                "(X > 1) - 1", "ArithExpr: first operand '(X > 1)' is not numeric or variable");
        for (var c : cases.entrySet()) {
            var e = assertThrows(AslSyntaxException.class, () -> parser.parse("+!g <- Y = " + c.getKey() + ".\n", "m.asl"));
            assertTrue(e.getMessage().contains("m.asl:1:12: error: " + c.getValue()), e.getMessage());
        }
        parser.parse("+!g <- Y = X + 1 - Z * 2 ** -W / math.abs(V) + .length(L) mod 3.\n", "m.asl");
    }

    @Test
    void syntaxErrorsNameFileLineAndColumn() {
        var e = assertThrows(AslSyntaxException.class, () -> parser.parse("!start.\n+!start <- .print(\"a\" ; b.\n", "bad.asl"));
        assertTrue(e.errors().get(0).toString().startsWith("bad.asl:2:"), e.getMessage());
        assertTrue(e.getMessage().contains(": error: "), e.getMessage());
        var lexical = assertThrows(AslSyntaxException.class, () -> parser.parse("p(1) # q.\n", "lex.asl"));
        assertTrue(lexical.errors().get(0).toString().startsWith("lex.asl:1:6: error:"), lexical.getMessage());
    }

    /**
     * A bracket left open or a string left open is told where the text went wrong, once, not as
     * "cannot read '(' here" at the bracket that opened fine.
     */
    @Test
    void anOpenBracketOrStringIsToldWhereItShouldHaveClosed() {
        Map<String, String> cases = Map.of(
                "!start.\n+!start <- .print(\"hi\"; .stopMAS.\n",
                "m.asl:2:23: error: expected ')' before ';': the '(' at 2:18 is not closed",
                "+g <- -+x(1.\n", "m.asl:1:12: error: expected ')' before '.': the '(' at 1:10 is not closed",
                "p(1\n!g.\n", "m.asl:2:3: error: expected ')' before '.': the '(' at 1:2 is not closed",
                "+!g <- .print([a, b(1); c.\n", "m.asl:1:23: error: expected ']' before ';': the '[' at 1:15 is not closed",
                "+!g <- .print(\"hi).\n+!h <- true.\n", "m.asl:1:15: error: a string is not closed on its line (a '\"' is missing)");
        for (var c : cases.entrySet()) {
            var e = assertThrows(AslSyntaxException.class, () -> parser.parse(c.getKey(), "m.asl"), c.getKey());
            assertEquals(c.getValue(), e.getMessage(), c.getKey());
        }
        // a closed bracket keeps ANTLR's own message
        var e = assertThrows(AslSyntaxException.class, () -> parser.parse("+!g <- .print(\"hi\") .stopMAS.\n", "m.asl"));
        assertTrue(e.getMessage().startsWith("m.asl:1:21: error: "), e.getMessage());
    }

    /**
     * Two terms side by side are told at the second with what should have come between them, by
     * where they are, once, not as "cannot read '(' here" at the arguments' bracket.
     */
    @Test
    void aMissingSeparatorIsToldWithWhatWasExpected() {
        Map<String, String> cases = Map.of(
                "!g.\n+!g <- .print(\"a\" \"b\").\n", "m.asl:2:19: error: expected ',' or ')' before '\"b\"'",
                "+!g <- .print(\"a\") .print(\"b\").\n", "m.asl:1:20: error: expected ';' or '.' before '.print'",
                "+!g <- X = 1 Y = 2.\n", "m.asl:1:14: error: expected ';' or '.' before 'Y'",
                "+!g <- .print([a, b c]).\n", "m.asl:1:21: error: expected ',', '|' or ']' before 'c'",
                "+!g <- if (a) { b !c }.\n", "m.asl:1:19: error: expected ';' or '}' before '!'",
                "+!g <- if (a b) { c }.\n", "m.asl:1:14: error: expected an operator or ')' before 'b'",
                "+!g <- .print(p[x], 1 2).\n", "m.asl:1:23: error: expected ',' or ')' before '2'",
                "+!g : a b <- c.\n", "m.asl:1:9: error: expected '&', '|', '<-' or '.' before 'b'",
                "r(X) :- p(X) q(X).\n", "m.asl:1:14: error: expected '&', '|' or '.' before 'q'");
        for (var c : cases.entrySet()) {
            var e = assertThrows(AslSyntaxException.class, () -> parser.parse(c.getKey(), "m.asl"), c.getKey());
            assertEquals(c.getValue(), e.getMessage(), c.getKey());
        }
    }

    @Test
    void syntaxErrorsSayWhatWasExpectedInAgentSpeaksWords() {
        var e = assertThrows(AslSyntaxException.class, () -> parser.parse("+!g <- !ns::.\n", "ns.asl"));
        String msg = e.errors().get(0).message();
        assertTrue(msg.contains("an atom or a variable"), msg);
        assertTrue(!msg.contains("NS_ATOM") && !msg.contains("VAR,") && !msg.contains("expecting"), msg);
        var extra = assertThrows(AslSyntaxException.class, () -> parser.parse("b(1)).\n", "x.asl"));
        assertEquals("unexpected ')', expected ':-' or '.'", extra.errors().get(0).message());
        // the token ',' among those expected is named whole, not cut at its own comma
        assertEquals("unexpected ';', expected '**', ',' or '['",
                ErrorCollector.inAgentSpeak("mismatched input ';' expecting {'**', ',', '['}", null, null));
    }

    @Test
    void goalConditionsAreReadAndPrintedAfterTheContext() throws Exception {
        Plan p = parser.parse("+!g(X) : X > 0 <: done(X) <- .print(X).\n", "gc.asl").plans().get(0);
        assertEquals("done(X)", p.goalCondition().toString());
        assertEquals("(X > 0)", p.context().toString());
        assertEquals("+!g(X) : (X > 0) <: done(X) <- .print(X).", p.toString());
        assertEquals(null, parser.parse("+!g <- .print(x).\n", "gc.asl").plans().get(0).goalCondition());
    }

    @Test
    void includeDirectivesMergeFilesAndReportMissingOnes(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("lib.asl"), "shared(1).\n+!lib <- .print(lib).\n");
        Files.writeString(dir.resolve("main.asl"), "{ include(\"lib.asl\") }\n!lib.\n");
        var program = parser.parseFile(dir.resolve("main.asl"));
        assertEquals(1, program.beliefs().size());
        assertEquals(1, program.plans().size());
        Files.writeString(dir.resolve("broken.asl"), "{ include(\"missing.asl\") }\n");
        var e = assertThrows(AslSyntaxException.class, () -> parser.parseFile(dir.resolve("broken.asl")));
        assertTrue(e.getMessage().contains("broken.asl:1:1: error: included file 'missing.asl' not found"), e.getMessage());
    }

    /** A fresh parser resumed from another's reading is left as that reading left the other. */
    @Test
    void aResumedParserNumbersAndKnowsFunctionsAsTheOneThatRead() throws Exception {
        String text = "{ register_function(\"twice\", 1, \"twice\") }\n"
                + "{ include(\"x.asl\", _) }\n"
                + "twice(X, Y) :- Y = X * 2.\n"
                + "+!g(_) : p(_, _) <- .print(twice(2)).\n";
        SourceResolver includes = (file, from) -> new SourceResolver.Source(file, "+!h(_) <- true.\n", file);
        var reader = new AslParser(includes);
        assertTrue(reader.isFresh());
        var program = reader.parse(new SourceResolver.Source("a.asl", text, "a.asl"));
        assertFalse(reader.isFresh());
        assertEquals(1, program.functions().size());
        var resumed = new AslParser(includes);
        resumed.resume(program, reader.varCounter().get(), reader.namespacesNumbered());
        assertEquals(reader.varCounter().get(), resumed.varCounter().get());
        assertEquals(reader.freshNamespace(), resumed.freshNamespace());
        // the next fresh variables get the same numbers
        assertEquals(reader.parseTerm("q(_, _)").toString(), resumed.parseTerm("q(_, _)").toString());
        assertThrows(IllegalStateException.class, () -> resumed.resume(program, 1, 0));
    }
}
