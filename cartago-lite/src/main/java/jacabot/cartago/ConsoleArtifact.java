package jacabot.cartago;

/**
 * The {@code console} artifact of every workspace: {@code println(...)} and {@code print(...)}
 * write {@code [agent] text} to the workspace's console, as Jason's console does. Arguments are
 * concatenated; strings print without quotes and integral numbers without ".0".
 */
public class ConsoleArtifact extends Artifact {
    /** Prints the arguments on one line. */
    @OPERATION
    void println(Object... args) {
        core().workspace().console().println(line(args));
    }

    /** Prints the arguments without ending the line. */
    @OPERATION
    void print(Object... args) {
        core().workspace().console().print(line(args));
    }

    private String line(Object[] args) {
        StringBuilder text = new StringBuilder("[").append(getCurrentOpAgentId()).append("] ");
        for (Object arg : args) {
            text.append(Values.text(arg));
        }
        return text.toString();
    }
}
