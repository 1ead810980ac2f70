package jacabot.app.replay;

import jacabot.app.inspector.Inspector;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * A team's run folder ({@code runs/team-delivery-...}): one folder per robot, each with the
 * robot's own step log ({@link TeamTap}), so each replays as a run of one robot; together they
 * are the team's run.
 */
public final class TeamRuns {
    private TeamRuns() {
    }

    /** {@return the robots' folders that hold a step log, by robot name; empty when {@code dir} is no team's folder} */
    public static List<Path> robotDirs(Path dir) throws IOException {
        if (!Files.isDirectory(dir) || Files.isRegularFile(dir.resolve(StepLog.FILE))) {
            return List.of();
        }
        var out = new ArrayList<Path>();
        try (Stream<Path> children = Files.list(dir)) {
            children.filter(c -> Files.isRegularFile(c.resolve(StepLog.FILE))).sorted().forEach(out::add);
        }
        return out;
    }

    /**
     * Shows a recorded team run in {@code inspector}: every robot's agent (named as its robot), its
     * whole history read on demand, the world and the team's plots. {@return the first robot's archive}
     *
     * @throws IOException when {@code dir} holds no robot's step log
     */
    public static StepArchive show(Inspector inspector, Path dir) throws IOException {
        List<Path> robots = robotDirs(dir);
        if (robots.isEmpty()) {
            throw new IOException(dir + ": no robot folder with a " + StepLog.FILE);
        }
        StepArchive first = null;
        for (Path r : robots) {
            StepArchive a = StepArchive.history(inspector, r, r.getFileName().toString());
            first = first == null ? a : first;
        }
        inspector.world(first.header().start());
        inspector.showPlots(dir);
        return first;
    }
}
