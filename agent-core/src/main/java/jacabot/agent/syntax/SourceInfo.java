package jacabot.agent.syntax;

/** Where a piece of AgentSpeak code comes from; lines and columns start at 1. */
public record SourceInfo(String file, int line, int column) {
    public static final SourceInfo NONE = new SourceInfo("", 0, 0);

    @Override
    public String toString() {
        return file + ":" + line + ":" + column;
    }
}
