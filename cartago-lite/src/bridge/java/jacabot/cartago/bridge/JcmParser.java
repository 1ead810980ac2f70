package jacabot.cartago.bridge;

import jacabot.cartago.bridge.JcmProject.AgentDecl;
import jacabot.cartago.bridge.JcmProject.ArtifactDecl;
import jacabot.cartago.bridge.JcmProject.WorkspaceDecl;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A recursive-descent reader of JaCaMo's project format, for the part jacabot runs:
 *
 * <pre>
 * project   := "mas" NAME "{" entry* "}"
 * entry     := "agent" NAME [":" SOURCE] ["{" param* "}"]
 *            | "workspace" NAME ["{" (artifact | "agents" ":" names)* "}"]
 *            | ("class-path" | "asl-path") ":" names
 * param     := ("beliefs" | "goals") ":" TEXT-TO-END-OF-LINE (continued after a trailing comma)
 *            | ("focus" | "join") ":" names | "instances" ":" NUMBER | "ag-arch" ":" CLASS
 * artifact  := "artifact" NAME ":" CLASS ["(" ARGS ")"]
 * </pre>
 *
 * Comments are {@code //} and {@code /* *}{@code /}. Anything else (an {@code organisation}, a
 * {@code platform:}, an agent's {@code roles:}) is refused with {@code file:line:col: error: ...}.
 */
final class JcmParser {
    /** A mistake in the file, located. */
    static final class JcmError extends Exception {
        private static final long serialVersionUID = 1L;

        JcmError(String message) {
            super(message);
        }
    }

    private static final Set<String> UNSUPPORTED_HINTS = Set.of("organisation", "organization");
    private final Path file;
    private final String text;
    /** Each {@code focus:} and {@code join:} entry as read, checked against the declared workspaces once all are read. */
    private final List<WorkspaceRef> workspaceRefs = new ArrayList<>();
    private int pos;

    private JcmParser(Path file, String text) {
        this.file = file;
        this.text = text;
    }

    static JcmProject parse(Path file, String text) throws JcmError {
        return new JcmParser(file, text).project();
    }

    private JcmProject project() throws JcmError {
        skip();
        keyword("mas");
        String name = name("the project's name");
        expect('{');
        var agents = new ArrayList<AgentDecl>();
        var workspaces = new ArrayList<WorkspaceDecl>();
        var classPath = new ArrayList<String>();
        var aslPath = new ArrayList<String>();
        block("an entry (agent, workspace, class-path, asl-path)", (word, at) -> {
            switch (word) {
                case "agent" -> agents.add(agent());
                case "workspace" -> workspaces.add(workspace());
                case "class-path" -> {
                    expect(':');
                    classPath.addAll(names());
                }
                case "asl-path" -> {
                    expect(':');
                    aslPath.addAll(names());
                }
                default -> throw error(at, UNSUPPORTED_HINTS.contains(word)
                        ? "organisations (Moise) are not supported: jacabot runs the agents and the environment of a .jcm"
                        : "'" + word + "' is not supported in a .jcm here (agent, workspace, class-path, asl-path)");
            }
        });
        skip();
        if (pos < text.length()) {
            throw error(pos, "unexpected text after the project's closing '}'");
        }
        checkWorkspaces(workspaces);
        return new JcmProject(file, name, agents, workspaces, classPath, aslPath);
    }

    private AgentDecl agent() throws JcmError {
        String name = name("the agent's name");
        skip();
        String source = name + ".asl";
        if (peek() == ':') {
            pos++;
            source = name("the agent's source file");
        }
        var p = new AgentParams();
        if (optionalBlock()) {
            block("an agent parameter (beliefs, goals, focus, join, instances, ag-arch)", (key, at) -> agentParam(p, key, at));
        }
        return new AgentDecl(name, source, p.beliefs, p.goals, p.focus, p.focusAt, p.join, p.instances, p.arch, p.optionsAt);
    }

    /** An agent's parameters as they are read. */
    private static final class AgentParams {
        String beliefs;
        String goals;
        final List<String> focus = new ArrayList<>();
        final List<String> focusAt = new ArrayList<>();
        final Map<String, String> optionsAt = new HashMap<>();
        final List<String> join = new ArrayList<>();
        int instances = 1;
        String arch;
    }

    private void agentParam(AgentParams p, String key, int at) throws JcmError {
        expect(':');
        switch (key) {
            case "beliefs" -> {
                p.optionsAt.putIfAbsent(key, where(at));
                p.beliefs = joined(p.beliefs, restOfEntry());
            }
            case "goals" -> {
                p.optionsAt.putIfAbsent(key, where(at));
                p.goals = joined(p.goals, restOfEntry());
            }
            case "focus" -> {
                var starts = new ArrayList<Integer>();
                List<String> names = names(starts);
                for (int i = 0; i < names.size(); i++) {
                    String f = names.get(i);
                    if (f.lastIndexOf('.') <= 0 || f.endsWith(".")) {
                        throw error(at, "focus '" + f + "' is not workspace.artifact");
                    }
                    p.focus.add(f);
                    p.focusAt.add(where(starts.get(i)));
                    workspaceRefs.add(new WorkspaceRef("focus", f, f.substring(0, f.lastIndexOf('.')), starts.get(i)));
                }
            }
            case "join" -> {
                var starts = new ArrayList<Integer>();
                List<String> names = names(starts);
                for (int i = 0; i < names.size(); i++) {
                    p.join.add(names.get(i));
                    workspaceRefs.add(new WorkspaceRef("join", names.get(i), names.get(i), starts.get(i)));
                }
            }
            case "instances" -> p.instances = number(at);
            case "ag-arch" -> p.arch = name("an architecture class");
            default -> throw error(at, ("roles".equals(key) ? "roles need an organisation, which is not supported"
                    : "the agent parameter '" + key + "' is not supported")
                    + " (beliefs, goals, focus, join, instances, ag-arch)");
        }
    }

    /** A {@code focus:} or {@code join:} entry ({@code key}), the workspace it names and where it starts. */
    private record WorkspaceRef(String key, String name, String workspace, int at) {
    }

    /**
     * A focus or a join names a workspace the project declares (or {@code main}, which is always
     * there): the agent's setup joins it first, and an undeclared one would only fail when the
     * agent starts, as its setup goal's failure.
     */
    private void checkWorkspaces(List<WorkspaceDecl> workspaces) throws JcmError {
        var declared = new LinkedHashSet<String>();
        declared.add("main");
        workspaces.forEach(w -> declared.add(w.name()));
        for (WorkspaceRef r : workspaceRefs) {
            if (!declared.contains(r.workspace())) {
                throw error(r.at(), r.key() + " '" + r.name() + "': no workspace '" + r.workspace()
                        + "' is declared (declared: " + String.join(", ", declared) + ")");
            }
        }
    }

    private WorkspaceDecl workspace() throws JcmError {
        String name = name("the workspace's name");
        var artifacts = new ArrayList<ArtifactDecl>();
        var agents = new ArrayList<String>();
        if (optionalBlock()) {
            block("artifact or agents:", (word, at) -> {
                if (word.equals("artifact")) {
                    String art = name("the artifact's name");
                    expect(':');
                    String cls = name("the artifact's class");
                    String args = "";
                    if (peek() == '(') {
                        args = parenthesised();
                    }
                    artifacts.add(new ArtifactDecl(art, cls, args, where(at)));
                } else if (word.equals("agents")) {
                    expect(':');
                    agents.addAll(names());
                } else {
                    throw error(at, "'" + word + "' is not supported in a workspace (artifact, agents)");
                }
            });
        }
        return new WorkspaceDecl(name, artifacts, agents);
    }

    // ---- lexical helpers ------------------------------------------------------------------------

    /** One entry of a block, read from its first word on ({@code at}: where that word starts). */
    @FunctionalInterface
    private interface EntryReader {
        void read(String word, int at) throws JcmError;
    }

    /** Reads a block's entries, each starting with a word ({@code what} names the kinds), up to and past its '}'. */
    private void block(String what, EntryReader entry) throws JcmError {
        while (!blockEnds()) {
            int at = pos;
            entry.read(name(what), at);
        }
    }

    /** {@return true (past it) at a '{' opening an optional block} */
    private boolean optionalBlock() throws JcmError {
        skip();
        if (peek() == '{') {
            pos++;
            return true;
        }
        return false;
    }

    /** {@return true (past it) at the '}' closing a block; an error at the end of the file} */
    private boolean blockEnds() throws JcmError {
        skip();
        if (peek() == '}') {
            pos++;
            return true;
        }
        if (pos >= text.length()) {
            throw error(pos, "expected '}' before the end of the file");
        }
        return false;
    }

    /** Skips blanks, new lines and comments. */
    private void skip() throws JcmError {
        while (pos < text.length()) {
            char c = text.charAt(pos);
            if (Character.isWhitespace(c)) {
                pos++;
            } else if (text.startsWith("//", pos)) {
                while (pos < text.length() && text.charAt(pos) != '\n') {
                    pos++;
                }
            } else if (text.startsWith("/*", pos)) {
                int end = text.indexOf("*/", pos + 2);
                if (end < 0) {
                    throw error(pos, "comment not closed");
                }
                pos = end + 2;
            } else {
                return;
            }
        }
    }

    private char peek() {
        return pos < text.length() ? text.charAt(pos) : '\0';
    }

    private void expect(char c) throws JcmError {
        skip();
        if (peek() != c) {
            throw error(pos, "expected '" + c + "'" + (pos < text.length() ? " here" : " before the end of the file"));
        }
        pos++;
    }

    private void keyword(String word) throws JcmError {
        int at = pos;
        String got = name("'" + word + "'");
        if (!got.equals(word)) {
            throw error(at, "expected '" + word + "', found '" + got + "'");
        }
    }

    /** A name, class, path or file: letters, digits and {@code _ - . / $}, or a quoted string. */
    private String name(String what) throws JcmError {
        skip();
        int start = pos;
        if (peek() == '"') {
            int end = text.indexOf('"', pos + 1);
            if (end < 0) {
                throw error(pos, "string not closed");
            }
            pos = end + 1;
            return text.substring(start + 1, end);
        }
        while (pos < text.length()) {
            char c = text.charAt(pos);
            if (Character.isLetterOrDigit(c) || c == '_' || c == '-' || c == '.' || c == '/' || c == '$' || c == '*') {
                pos++;
            } else {
                break;
            }
        }
        if (pos == start) {
            throw error(start, "expected " + what);
        }
        return text.substring(start, pos);
    }

    /** Names separated by commas, on one line (or continued after a comma). */
    private List<String> names() throws JcmError {
        return names(new ArrayList<>());
    }

    /** {@link #names()}, adding where each name starts to {@code starts}. */
    private List<String> names(List<Integer> starts) throws JcmError {
        var out = new ArrayList<String>();
        skip();
        starts.add(pos);
        out.add(name("a name"));
        while (true) {
            int save = pos;
            skipSpacesOnLine();
            if (peek() != ',') {
                pos = save;
                return out;
            }
            pos++;
            skip();
            starts.add(pos);
            out.add(name("a name after ','"));
        }
    }

    private void skipSpacesOnLine() {
        while (pos < text.length() && (text.charAt(pos) == ' ' || text.charAt(pos) == '\t')) {
            pos++;
        }
    }

    private int number(int at) throws JcmError {
        String n = name("a number");
        try {
            return Integer.parseInt(n);
        } catch (NumberFormatException e) {
            throw error(at, "instances must be a whole number, got '" + n + "'");
        }
    }

    /**
     * The text up to the end of the line, going on to the next lines while it ends with a comma,
     * or up to the '}' that closes the agent's block ({@code agent a { goals: g }} on one line).
     */
    private String restOfEntry() {
        var sb = new StringBuilder();
        while (true) {
            skipSpacesOnLine();
            int start = pos;
            boolean quoted = false;
            boolean closed = false;
            int depth = 0;
            while (pos < text.length() && text.charAt(pos) != '\n') {
                char c = text.charAt(pos);
                if (c == '"') {
                    quoted = !quoted;
                } else if (!quoted && text.startsWith("//", pos)) {
                    break;
                } else if (!quoted && (c == '(' || c == '[' || c == '{')) {
                    depth++;
                } else if (!quoted && (c == ')' || c == ']' || c == '}') && --depth < 0 && c == '}') {
                    closed = true; // the block's end: left for the block to read
                    break;
                }
                pos++;
            }
            String line = text.substring(start, pos).trim();
            if (closed) {
                return sb.append(line).toString();
            }
            while (pos < text.length() && text.charAt(pos) != '\n') {
                pos++; // a comment
            }
            sb.append(line);
            if (!line.endsWith(",") || pos >= text.length()) {
                return sb.toString();
            }
            sb.append(' ');
            pos++;
        }
    }

    /** The text between balanced parentheses (quotes respected); the cursor is on '('. */
    private String parenthesised() throws JcmError {
        int open = pos;
        int depth = 0;
        boolean quoted = false;
        for (; pos < text.length(); pos++) {
            char c = text.charAt(pos);
            if (c == '"') {
                quoted = !quoted;
            } else if (!quoted && c == '(') {
                depth++;
            } else if (!quoted && c == ')' && --depth == 0) {
                pos++;
                return text.substring(open + 1, pos - 1).trim();
            }
        }
        throw error(open, "'(' not closed");
    }

    private static String joined(String a, String b) {
        return a == null ? b : a + ", " + b;
    }

    String where(int at) {
        int line = 1;
        int col = 1;
        for (int i = 0; i < at && i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                line++;
                col = 1;
            } else {
                col++;
            }
        }
        return file + ":" + line + ":" + col;
    }

    private JcmError error(int at, String message) {
        return new JcmError(where(at) + ": error: " + message);
    }
}
