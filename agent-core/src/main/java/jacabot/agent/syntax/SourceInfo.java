package jacabot.agent.syntax;

/** Where a piece of AgentSpeak code comes from; lines and columns start at 1. */
public record SourceInfo(String file, int line, int column) {
    public static final SourceInfo NONE = new SourceInfo("", 0, 0);

    /**
     * {@return the source as Jason names it in failure annotations and plan labels: {@code file:a.asl}}
     * The file name only, as a project names its agents' files: never a path of this machine.
     */
    public String jasonFile() {
        int slash = Math.max(file.lastIndexOf('/'), file.lastIndexOf('\\'));
        return "file:" + file.substring(slash + 1);
    }

    /**
     * {@return the source as Jason's {@code .get_src_info} names it: as {@link #jasonFile}, or ""
     * for code read from a string at run time (whose parser names it {@code <term>} or {@code <plan>})}
     */
    public String jasonSrc() {
        return file.startsWith("<") ? "" : jasonFile();
    }

    /** {@return the position as Jason prints it in messages: {@code file:path:line}} */
    public String jasonPosition() {
        return jasonFile() + ":" + line;
    }

    @Override
    public String toString() {
        return file + ":" + line + ":" + column;
    }
}
