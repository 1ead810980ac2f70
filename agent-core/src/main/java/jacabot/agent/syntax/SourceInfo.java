package jacabot.agent.syntax;

/** Where a piece of AgentSpeak code comes from; lines and columns start at 1. */
public record SourceInfo(String file, int line, int column) {
    public static final SourceInfo NONE = new SourceInfo("", 0, 0);

    /** {@return the source as Jason names it in failure annotations: {@code file:path}} */
    public String jasonFile() {
        return "file:" + file;
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
