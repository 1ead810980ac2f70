package jacabot.app.cli;

import jacabot.app.sweep.TeamDeliveryRun;
import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.TeamLockstep;
import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * {@code jacabot controller --lockstep} with a team world: the controllers' process of a team in two
 * processes (thesis Chapter 6). One {@link RobotController} per robot, robot i connecting to the
 * middleware's port + i, all stepped together ({@link TeamLockstep}); the agents' process is {@code
 * jacabot experiment team-delivery --remote-controller} with the same world file, team and seed.
 * The world is here, so are its ground truth's summaries and event logs ({@code --out DIR}).
 */
final class TeamControllerRun {
    /** How often the wait for the agents' process says whom it waits for. */
    private static final long WAIT_NOTE_MS = 10_000;

    private final SimWorld world;
    private final ControllerConfig config;
    private final String host;
    private final int port;
    private final Path out;
    private final boolean linkLogs;
    private final PrintWriter stdout;

    /** @param config every robot's config but its robot, port and event log */
    TeamControllerRun(SimWorld world, ControllerConfig config, String host, int port, Path out, boolean linkLogs, PrintWriter stdout) {
        this.world = world;
        this.config = config;
        this.host = host;
        this.port = port;
        this.out = out;
        this.linkLogs = linkLogs;
        this.stdout = stdout;
    }

    /** Runs {@code seconds} (null: until every robot's link has ended, or Ctrl-C). */
    int run(Double seconds) throws InterruptedException {
        int n = world.robots().size();
        List<Writer> logs = new ArrayList<>();
        List<RobotController> controllers = new ArrayList<>();
        try {
            for (int i = 0; i < n; i++) {
                String robot = world.robots().get(i).name();
                ControllerConfig cc = config.withRobot(robot).withAddress(host, port + i);
                if (out != null && linkLogs) {
                    Writer w = writer(Files.createDirectories(out.resolve(robot)).resolve("link-log.txt"));
                    logs.add(w);
                    cc = cc.withEventLog(LineSink.into(w));
                }
                controllers.add(new RobotController(world, cc));
            }
        } catch (IOException e) {
            closeAll(logs);
            throw OutPlace.cannotWrite("--out", out, e);
        }
        List<RunRecorder> recorders = TeamDeliveryRun.attach(world);
        TeamLockstep team = new TeamLockstep(world, controllers, null);
        stdout.println(String.format(Locale.ROOT, "controller: a team of %d robots (%s) of world '%s', lockstep; their middlewares at %s:%d..%d",
                n, String.join(", ", world.robots().stream().map(r -> r.name()).toList()), world.name(), host, port, port + n - 1));
        stdout.flush();
        ExitHook hook = ExitHook.install("controller-shutdown", () -> {
            team.close();
            closeAll(logs);
        });
        try {
            controllers.forEach(RobotController::start);
            if (!awaitAgents(team)) {
                return 0;
            }
            long end = seconds == null ? Long.MAX_VALUE : world.timeMs() + Math.round(seconds * 1000);
            while (world.timeMs() < end && team.anyConnected() && !team.interrupted()) {
                team.runner().stepOnce();
            }
        } finally {
            team.close();
            closeAll(logs);
            hook.remove();
        }
        List<RunSummary> summaries = TeamDeliveryRun.summaries(recorders, TeamDeliveryRun.AGENTS);
        for (RunSummary s : summaries) {
            stdout.println(String.format(Locale.ROOT, "[%s] picks %d, deliveries %d, contact %.1f s, fail-safe trips %d",
                    s.robot(), s.picks(), s.deliveries(), s.contactTime(), controllers.get(summaries.indexOf(s)).failSafeTrips()));
        }
        if (out != null) {
            write(summaries);
        }
        stdout.println(String.format(Locale.ROOT, "controller: stopped at t=%.2f s", world.time()));
        stdout.flush();
        return 0;
    }

    /** Waits until every robot's middleware took its link; {@return false when interrupted meanwhile} */
    private boolean awaitAgents(TeamLockstep team) throws InterruptedException {
        while (true) {
            List<String> missing = team.awaitConnected(WAIT_NOTE_MS);
            if (missing.isEmpty()) {
                return true;
            }
            stdout.println("controller: waiting for the agents' process (`jacabot experiment team-delivery --remote-controller`) to take the links of "
                    + String.join(", ", missing));
            stdout.flush();
            if (Thread.currentThread().isInterrupted()) {
                return false;
            }
        }
    }

    private void write(List<RunSummary> summaries) {
        try {
            for (RunSummary r : summaries) {
                Path dir = Files.createDirectories(out.resolve(r.robot()));
                r.writeJson(dir.resolve("summary.json"));
                Files.writeString(dir.resolve("event-log.txt"), r.eventLog());
            }
        } catch (IOException e) {
            throw OutPlace.cannotWrite("--out", out, e);
        }
        stdout.println("Written: per robot " + out.resolve("ROBOT") + "/summary.json, event-log.txt" + (linkLogs ? ", link-log.txt" : ""));
    }

    private static Writer writer(Path file) throws IOException {
        return Files.newBufferedWriter(file, StandardCharsets.UTF_8);
    }

    private static void closeAll(List<Writer> writers) {
        for (Writer w : writers) {
            try {
                w.close();
            } catch (IOException e) {
                // the run is over; nothing more to say
            }
        }
    }
}
