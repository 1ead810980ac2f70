package jacabot.app.cli;

import java.util.ArrayList;
import java.util.List;

/**
 * The training run of the class-data sharing archive (build.gradle, {@code installDist}): several
 * launcher command lines, separated by {@code --then}, run one after the other in one JVM, so
 * that the archive the JVM writes at its exit ({@code -XX:ArchiveClassesAtExit}) holds the classes
 * of each: an AgentSpeak project's ({@code jacabot run}) and a headless experiment's (the world,
 * the middleware, the step log, the plots). Exits with the largest exit code of the commands.
 */
public final class ArchiveTraining {
    static final String THEN = "--then";

    private ArchiveTraining() {
    }

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /** {@return the largest exit code of the command lines in {@code args}} */
    static int run(String... args) {
        int code = 0;
        for (List<String> command : commands(args)) {
            code = Math.max(code, JacabotCommand.execute(command.toArray(new String[0])));
        }
        return code;
    }

    /** {@return the command lines, split at {@value #THEN}} */
    static List<List<String>> commands(String... args) {
        var out = new ArrayList<List<String>>();
        var part = new ArrayList<String>();
        for (String a : args) {
            if (a.equals(THEN)) {
                out.add(List.copyOf(part));
                part.clear();
            } else {
                part.add(a);
            }
        }
        out.add(List.copyOf(part));
        out.removeIf(List::isEmpty);
        return out;
    }
}
