package jacabot.app.console;

/** How much a command prints: {@code --quiet}, the default, {@code --verbose}. */
public enum Verbosity {
    /** The results (summary, written files), warnings and errors only. */
    QUIET,
    /** Also jacabot's own lines, the progress line and the agents' story, repeated lines folded. */
    NORMAL,
    /** Also every agent line as printed (nothing folded) and the link's and controller's details. */
    VERBOSE;

    /** {@return the level of a command line's {@code --quiet}/{@code --verbose} flags} */
    public static Verbosity of(boolean quiet, boolean verbose) {
        if (quiet && verbose) {
            throw new IllegalArgumentException("--quiet and --verbose exclude each other");
        }
        return quiet ? QUIET : verbose ? VERBOSE : NORMAL;
    }
}
