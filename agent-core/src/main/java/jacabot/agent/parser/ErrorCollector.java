package jacabot.agent.parser;

import jacabot.agent.syntax.SourceInfo;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.BufferedTokenStream;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenStream;

/**
 * The one funnel for lexer and parser errors: each becomes a {@link SyntaxError} with its
 * position, its message in AgentSpeak's terms ("expected an atom or a variable") instead of the
 * grammar's token names.
 */
final class ErrorCollector extends BaseErrorListener {
    private final String file;
    private final List<SyntaxError> errors = new ArrayList<>();

    /** What the grammar's named tokens are in AgentSpeak's words. */
    private static final Map<String, String> WORDS = Map.ofEntries(Map.entry("ATOM", "an atom"),
            Map.entry("VAR", "a variable"), Map.entry("UNNAMEDVAR", "a variable"),
            Map.entry("NS_ATOM", "a namespace (ns::)"), Map.entry("NS_VAR", "a namespace (ns::)"),
            Map.entry("NUMBER", "a number"), Map.entry("STRING", "a string"), Map.entry("RBRACE", "'}'"),
            Map.entry("<EOF>", "the end of the file"), Map.entry("EOF", "the end of the file"),
            Map.entry("ERROR_CHAR", "a character"), Map.entry("ID", "a name"));

    private static final int MAX_EXPECTED = 12;
    private static final Pattern INPUT = Pattern.compile("(?:mismatched|extraneous) input (.*) expecting (.*)");
    private static final Pattern MISSING = Pattern.compile("missing (.*) at (.*)");
    private static final Pattern NO_VIABLE = Pattern.compile("no viable alternative at input (.*)");
    private static final Pattern LEXER = Pattern.compile("token recognition error at: (.*)");
    /** One token of ANTLR's set: a quoted literal (which may be {@code ','}) or a name. */
    private static final Pattern TOKEN = Pattern.compile("'(?:[^'\\\\]|\\\\.)*'|[^,\\s{}]+");

    ErrorCollector(String file) {
        this.file = file;
    }

    /** Set once a string left open is told: the errors after it are its consequences. */
    private boolean openString;
    /** The token where an open bracket was told: ANTLR's errors up to it are its consequences. */
    private int quietUntil = -1;

    @Override
    public void syntaxError(Recognizer<?, ?> recognizer, Object offendingSymbol, int line, int col,
            String msg, RecognitionException e) {
        if (openString) {
            return;
        }
        if (recognizer instanceof Parser parser && offendingSymbol instanceof Token at) {
            if (at.getTokenIndex() <= quietUntil) {
                return;
            }
            // ANTLR tells these where its prediction began (an opening '(' that is fine), not
            // where the text went wrong: said at the cause instead
            if (parser.getTokenStream() instanceof BufferedTokenStream all) {
                all.fill(); // the rest of the text too: the cause may come after the token told
            }
            Token quote = strayQuote(parser.getTokenStream(), at);
            if (quote != null) {
                openString = true;
                errors.add(new SyntaxError(new SourceInfo(file, quote.getLine(), quote.getCharPositionInLine() + 1),
                        "a string is not closed on its line (a '\"' is missing)"));
                return;
            }
            if (NO_VIABLE.matcher(msg).matches()) {
                Token cause = unclosed(parser.getTokenStream(), at);
                if (cause != null) {
                    quietUntil = cause.getTokenIndex();
                    return;
                }
                Token end = juxtaposed(parser.getTokenStream(), at);
                if (end != null) {
                    quietUntil = end.getTokenIndex();
                    return;
                }
            }
        }
        errors.add(new SyntaxError(new SourceInfo(file, line, col + 1), inAgentSpeak(msg, recognizer, e)));
    }

    /** {@return a lone '"' (the lexer's one-character token) up to the offending token's line, or null} */
    private static Token strayQuote(TokenStream tokens, Token at) {
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            if (t.getType() == Token.EOF || t.getLine() > at.getLine()) {
                return null;
            }
            if (t.getType() == AgentSpeakLexer.ERROR_CHAR && "\"".equals(t.getText())) {
                return t;
            }
        }
        return null;
    }

    /**
     * {@return the error at the token that comes where the '(' or '[' {@code open} should have
     * been closed (a ';', '<-', ':-', the clause's '.', the end of the file, a bracket of the other
     * kind), told as an error; or null when it is closed}
     */
    private Token unclosed(TokenStream tokens, Token open) {
        if (!open.getText().equals("(") && !open.getText().equals("[")) {
            return null;
        }
        var stack = new ArrayDeque<Token>();
        for (int i = open.getTokenIndex(); i < tokens.size(); i++) {
            Token t = tokens.get(i);
            String x = t.getType() == Token.EOF ? "<EOF>" : t.getText();
            Token top = stack.peek();
            if (CLOSES.containsValue(x)) {
                stack.push(t);
            } else if (CLOSES.containsKey(x) && top != null && CLOSES.get(x).equals(top.getText())) {
                stack.pop();
                if (stack.isEmpty()) {
                    return null;
                }
            } else if (top != null && !top.getText().equals("{") && (CLOSES.containsKey(x) || ENDS.contains(x))) {
                String closer = top.getText().equals("(") ? ")" : "]";
                errors.add(new SyntaxError(new SourceInfo(file, t.getLine(), t.getCharPositionInLine() + 1),
                        "expected '" + closer + "' before '" + x + "': the '" + top.getText() + "' at " + top.getLine()
                                + ":" + (top.getCharPositionInLine() + 1) + " is not closed"));
                return t;
            } else if (CLOSES.containsKey(x) || ENDS.contains(x) && top == null) {
                return null;
            }
        }
        return null;
    }

    /**
     * {@return the clause's end, after telling an error at the first term that follows another with
     * nothing between them ({@code .print("a" "b")}, {@code a(1) b(2)} without the ';'), from
     * {@code at} (the token ANTLR told, which may be the '(' of a list of arguments that went
     * wrong further on) to the clause's end; null when there is none: what separates them is
     * said by where they are (in a '(', a '[', a '{', a plan's body)}
     */
    private Token juxtaposed(TokenStream tokens, Token at) {
        int clauseEnd = -1;
        int depth = 0;
        for (int i = at.getTokenIndex(); i < tokens.size(); i++) {
            Token t = tokens.get(i);
            String x = t.getText();
            if (t.getType() == Token.EOF || depth == 0 && ".".equals(x)) {
                clauseEnd = i;
                break;
            }
            if (CLOSES.containsValue(x)) {
                depth++;
            } else if (CLOSES.containsKey(x)) {
                depth--;
            }
        }
        if (clauseEnd < 0) {
            return null;
        }
        for (int i = Math.max(at.getTokenIndex(), 1); i < clauseEnd; i++) {
            Token b = tokens.get(i);
            if (endsTerm(tokens.get(i - 1)) && startsTerm(b)) {
                String expected = separators(tokens, i);
                if (expected == null) {
                    return null;
                }
                errors.add(new SyntaxError(new SourceInfo(file, b.getLine(), b.getCharPositionInLine() + 1),
                        "expected " + expected + " before '" + b.getText() + "'"));
                return tokens.get(clauseEnd);
            }
        }
        return null;
    }

    /**
     * {@return what may separate two terms at token {@code i}, by the innermost bracket open there
     * in its clause: ',' or ')' in a structure's arguments, ',' '|' or ']' in a list, ';' or '}'
     * in a block, ';' or '.' in a plan's body, '&', '|', '<-' or '.' in its context, '&', '|' or
     * '.' in a rule's body, an operator or ')' in other parentheses; null elsewhere (a belief's
     * or a trigger's literal: left to ANTLR)}
     */
    private static String separators(TokenStream tokens, int i) {
        int depth = 0;
        for (int j = i - 1; j >= 0; j--) {
            Token t = tokens.get(j);
            String x = t.getText();
            if (CLOSES.containsKey(x)) {
                depth++;
            } else if (CLOSES.containsValue(x) && depth > 0) {
                depth--;
            } else if (CLOSES.containsValue(x)) {
                return switch (x) {
                    case "(" -> j > 0 && tokens.get(j - 1).getType() == AgentSpeakLexer.ATOM ? "',' or ')'" : "an operator or ')'";
                    case "[" -> "',', '|' or ']'";
                    default -> "';' or '}'";
                };
            } else if (depth == 0 && "<-".equals(x)) {
                return "';' or '.'";
            } else if (depth == 0 && ":".equals(x)) {
                return "'&', '|', '<-' or '.'";
            } else if (depth == 0 && ":-".equals(x)) {
                return "'&', '|' or '.'";
            } else if (depth == 0 && ".".equals(x)) {
                return null;
            }
        }
        return null;
    }

    /** {@return whether a term may end with this token (a '}' may close a block, which needs no ';' after it)} */
    private static boolean endsTerm(Token t) {
        return TERM_TOKENS.contains(t.getType()) || Set.of(")", "]", "true", "false").contains(t.getText());
    }

    /**
     * {@return whether a term or a body formula may start with this token ('+', '-' and '(' may
     * continue one, a '[' may be a literal's annotations)}
     */
    private static boolean startsTerm(Token t) {
        return TERM_TOKENS.contains(t.getType()) || t.getType() == AgentSpeakLexer.NS_ATOM
                || t.getType() == AgentSpeakLexer.NS_VAR || Set.of("!", "!!", "?", "~", "not", "true", "false").contains(t.getText());
    }

    /** Tokens that are a term by themselves. */
    private static final Set<Integer> TERM_TOKENS = Set.of(AgentSpeakLexer.STRING, AgentSpeakLexer.NUMBER,
            AgentSpeakLexer.ATOM, AgentSpeakLexer.VAR, AgentSpeakLexer.UNNAMEDVAR);

    /** What closes what. */
    private static final Map<String, String> CLOSES = Map.of(")", "(", "]", "[", "}", "{");
    /** Tokens that never come inside an open '(' or '[' (a plan term's braces aside). */
    private static final Set<String> ENDS = Set.of(";", "<-", ":-", ".", "<EOF>");

    /** {@return ANTLR's message said with AgentSpeak's words} */
    static String inAgentSpeak(String msg, Recognizer<?, ?> recognizer, RecognitionException e) {
        Matcher m = INPUT.matcher(msg);
        if (m.matches()) {
            return "unexpected " + m.group(1) + ", expected " + expected(m.group(2));
        }
        m = MISSING.matcher(msg);
        if (m.matches()) {
            return "expected " + expected(m.group(1)) + " before " + m.group(2);
        }
        m = NO_VIABLE.matcher(msg);
        if (m.matches()) {
            // what may come there, when that says something (at a term's start, nearly anything may)
            var may = e == null ? null : e.getExpectedTokens();
            String more = may == null || may.isNil() || may.size() > MAX_EXPECTED ? ""
                    : ", expected " + expected(may.toString(recognizer.getVocabulary()));
            return "cannot read " + m.group(1) + " here" + more;
        }
        m = LEXER.matcher(msg);
        if (m.matches()) {
            return "unexpected character " + m.group(1);
        }
        return msg;
    }

    /** {@code {NS_ATOM, NS_VAR, '('}} as "a namespace (ns::) or '('". */
    private static String expected(String tokens) {
        String inner = tokens.startsWith("{") && tokens.endsWith("}") ? tokens.substring(1, tokens.length() - 1) : tokens;
        var words = new LinkedHashSet<String>();
        // not split at commas: the token ',' is one of them
        Matcher t = TOKEN.matcher(inner);
        while (t.find()) {
            words.add(WORDS.getOrDefault(t.group(), t.group()));
        }
        var list = new ArrayList<>(words);
        if (list.size() == 1) {
            return list.get(0);
        }
        return String.join(", ", list.subList(0, list.size() - 1)) + " or " + list.get(list.size() - 1);
    }

    void add(SourceInfo where, String message) {
        errors.add(new SyntaxError(where, message));
    }

    /** Adds {@code more} to the error told at {@code where} with {@code message}, once a later rule knows the likely cause. */
    void amend(SourceInfo where, String message, String more) {
        errors.replaceAll(e -> e.where().equals(where) && e.message().equals(message) ? new SyntaxError(where, message + more) : e);
    }

    List<SyntaxError> errors() {
        return errors;
    }
}
