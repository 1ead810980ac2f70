package jacabot.agent.parser;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import java.util.List;
import java.util.Set;

/**
 * A term written plainly, an atom ({@code x42}) or a number ({@code 42}, {@code 4.2}), read
 * without the parser: {@code .term2string(T, S)} mostly reads such texts, and a parser made for
 * each took most of its time. Anything else is left to {@link AslParser#parseTerm}.
 */
final class PlainTerm {
    /** Words the grammar reads otherwise than as an atom (or reads as a constant: true, false). */
    private static final Set<String> RESERVED = Set.of("div", "mod", "not", "if", "elif", "else", "for", "while",
            "true", "false");

    private PlainTerm() {
    }

    /** {@return the term the parser would read from {@code text}, or null when it is not plain} */
    static Term read(String text) {
        int n = text.length();
        if (n == 0 || n > 64) {
            return null;
        }
        char c = text.charAt(0);
        if (c >= 'a' && c <= 'z') {
            for (int i = 1; i < n; i++) {
                if (!isNameChar(text.charAt(i))) {
                    return null;
                }
            }
            if (RESERVED.contains(text)) {
                return null;
            }
            // interned, as the parser's functors
            return new Literal(text.intern(), List.of(), List.of(), false, false, null);
        }
        if (c >= '0' && c <= '9') {
            int dot = -1;
            for (int i = 1; i < n; i++) {
                char d = text.charAt(i);
                if (d == '.' && dot < 0) {
                    dot = i;
                } else if (d < '0' || d > '9') {
                    return null;
                }
            }
            return dot == n - 1 ? null : new NumberTerm(Double.parseDouble(text));
        }
        return null;
    }

    private static boolean isNameChar(char c) {
        return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c >= '0' && c <= '9' || c == '_';
    }
}
