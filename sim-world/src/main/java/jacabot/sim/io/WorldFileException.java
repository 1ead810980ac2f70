package jacabot.sim.io;

/**
 * An invalid world file: where (a JSON path such as {@code $.cylinders[1].radius}) and what is
 * wrong. {@link #getMessage()} reads {@code file: $.path: problem}, fit for a command line to print
 * as is (exit code 2, no stack trace).
 */
public final class WorldFileException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String source;
    private final String jsonPath;
    private final String problem;

    /** @param source the file name, or null */
    public WorldFileException(String source, String jsonPath, String problem) {
        super((source == null ? "" : source + ": ") + jsonPath + ": " + problem);
        this.source = source;
        this.jsonPath = jsonPath;
        this.problem = problem;
    }

    /** {@return the JSON path of the faulty value, {@code $} for the whole document} */
    public String jsonPath() {
        return jsonPath;
    }

    /** {@return the problem, without file and path} */
    public String problem() {
        return problem;
    }

    /** {@return the file name, or null} */
    public String source() {
        return source;
    }
}
