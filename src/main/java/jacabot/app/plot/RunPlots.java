package jacabot.app.plot;

import java.io.PrintStream;
import java.nio.file.Path;

/** The run's plots (stub). */
public final class RunPlots {
    private RunPlots() {
    }

    public static void writeAll(Path outDir, PrintStream out) {
    }
}
