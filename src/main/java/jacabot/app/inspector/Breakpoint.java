package jacabot.app.inspector;

import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Where a run should halt, checked after each control step against the agent's mind then:
 * <ul>
 * <li>{@code label:NAME}: a plan labelled {@code @NAME} was selected;</li>
 * <li>{@code +!pick}, {@code -battery(_)}, {@code trigger:+!go(1)}: a plan was selected for an event
 * of that trigger ({@code _} stands for any term; without arguments, any arguments), or for a
 * belief pattern a belief of that form was added ({@code +}) or removed ({@code -});</li>
 * <li>{@code belief:PATTERN}: a belief of that form was added or removed;</li>
 * <li>{@code failure}: a goal failed (a plan was selected for a {@code -!goal} event);</li>
 * <li>{@code t=60s}: simulated time reached 60 s ({@code 90s}, {@code 2m}, {@code 1500ms}).</li>
 * </ul>
 */
public record Breakpoint(String kind, String text, Pattern event, Pattern belief, char sign, long timeMs) {
    /** {@return the breakpoint a spec names} @throws IllegalArgumentException with what is wrong */
    public static Breakpoint parse(String spec) {
        String s = spec.trim();
        if (s.startsWith("label:")) {
            String label = s.substring(6).replaceFirst("^@", "");
            if (label.isEmpty()) {
                throw new IllegalArgumentException("label: needs a plan label, e.g. label:avoidFront");
            }
            return new Breakpoint("label", s, Pattern.compile("@" + Pattern.quote(label) + "(\\s.*|\\[.*|)"), null, ' ', -1);
        }
        if (s.startsWith("t=")) {
            return new Breakpoint("time", s, null, null, ' ', millis(s.substring(2)));
        }
        if (s.equals("failure")) {
            return new Breakpoint("failure", s, Pattern.compile("-!.*"), null, ' ', -1);
        }
        if (s.startsWith("belief:")) {
            return new Breakpoint("belief", s, null, term(s.substring(7)), ' ', -1);
        }
        String trigger = s.startsWith("trigger:") ? s.substring(8) : s;
        if (trigger.matches("[+-][!?]?[a-z][A-Za-z0-9_]*(\\(.*\\))?")) {
            Pattern event = Pattern.compile(Pattern.quote(trigger.substring(0, 1)) + term(trigger.substring(1)).pattern());
            boolean onBelief = Character.isLetter(trigger.charAt(1));
            return new Breakpoint("trigger", s, event, onBelief ? term(trigger.substring(1)) : null, trigger.charAt(0), -1);
        }
        throw new IllegalArgumentException("'" + spec + "' is no breakpoint: label:NAME, +!goal, -belief(_), "
                + "belief:PATTERN, failure or t=60s");
    }

    /**
     * {@return null when this is no {@code label:} breakpoint, a plan of these labels has its
     * label or the labels are not known (null); else why it would never halt the run, with the
     * labels nearest to its own by spelling}
     */
    public String missingLabel(Collection<String> labels) {
        if (!kind.equals("label") || labels == null) {
            return null;
        }
        String label = text.substring(6).replaceFirst("^@", "");
        if (labels.contains(label)) {
            return null;
        }
        List<String> near = labels.stream().distinct()
                .sorted(Comparator.comparingInt((String l) -> distance(label.toLowerCase(Locale.ROOT), l.toLowerCase(Locale.ROOT)))
                        .thenComparing(Comparator.naturalOrder()))
                .limit(3).toList();
        return "the agent has no plan labelled @" + label
                + (near.isEmpty() ? " (it has no labelled plan)" : " (nearest: " + String.join(", ", near) + ")");
    }

    /** {@return the edit distance between two names (insertions, deletions, substitutions)} */
    private static int distance(String a, String b) {
        int[] row = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            row[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            int diag = row[0];
            row[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int up = row[j];
                row[j] = Math.min(Math.min(row[j] + 1, row[j - 1] + 1), diag + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1));
                diag = up;
            }
        }
        return row[b.length()];
    }

    /** A term pattern: {@code f} any {@code f(...)}; {@code f(a, _)} with {@code _} any term; annotations allowed. */
    private static Pattern term(String t) {
        String p = t.trim();
        // an unclosed pattern would be taken and never match: the run would never halt
        if (count(p, '(') != count(p, ')') || count(p, '[') != count(p, ']')) {
            throw new IllegalArgumentException("'" + p + "': its parentheses or brackets do not close");
        }
        if (!p.contains("(")) {
            return Pattern.compile(Pattern.quote(p) + "(\\(.*\\))?(\\[.*\\])?");
        }
        var out = new StringBuilder();
        for (String part : p.split("_", -1)) {
            if (out.length() > 0) {
                out.append("[^,]*?");
            }
            out.append(Pattern.quote(part.replace(" ", "")));
        }
        return Pattern.compile(out + "(\\[.*\\])?");
    }

    private static long count(String s, char c) {
        return s.chars().filter(x -> x == c).count();
    }

    private static long millis(String d) {
        String v = d.trim().toLowerCase(Locale.ROOT);
        try {
            if (v.endsWith("ms")) {
                return Long.parseLong(v.substring(0, v.length() - 2));
            }
            if (v.endsWith("m")) {
                return Math.round(Double.parseDouble(v.substring(0, v.length() - 1)) * 60_000);
            }
            return Math.round(Double.parseDouble(v.endsWith("s") ? v.substring(0, v.length() - 1) : v) * 1000);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("t=" + d + ": not a time (60s, 2m, 1500ms)");
        }
    }

    /**
     * {@return why the run halts after this step, or null}
     *
     * @param added beliefs added since the previous step (as text), {@code removed} those removed
     */
    public String hit(MindState mind, List<String> added, List<String> removed) {
        if (kind.equals("time")) {
            return mind.timeMs() >= timeMs ? "t=" + mind.timeMs() / 1000.0 + " s" : null;
        }
        if (event != null) {
            for (MindState.Selection s : mind.selections()) {
                String matched = kind.equals("label") ? s.plan() : s.event().replace(" ", "");
                if (event.matcher(matched).matches()) {
                    return "plan " + s.plan() + " selected for " + s.event();
                }
            }
        }
        if (belief == null) {
            return null;
        }
        return beliefChange(sign == '-' ? List.of() : added, sign == '+' ? List.of() : removed, belief);
    }

    private static String beliefChange(List<String> added, List<String> removed, Pattern p) {
        for (String b : added) {
            if (p.matcher(b.replace(" ", "")).matches()) {
                return "belief added: " + b;
            }
        }
        for (String b : removed) {
            if (p.matcher(b.replace(" ", "")).matches()) {
                return "belief removed: " + b;
            }
        }
        return null;
    }
}
