package jacabot.app.replay;

import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindProbe;
import jacabot.app.run.TeamLockstepRun;
import jacabot.agent.semantics.Agent;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.robot.Robot;
import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Taps a team's lockstep run as {@link RunTap} taps one robot's: after each control step, every
 * robot's agent's mind is captured once and handed to the inspector (one agent per robot, named as
 * the robot, beside the team's shared artifacts it perceives) and, with the robot's body, commands
 * and readings, to the robot's own step log, {@code DIR/ROBOT/}{@value StepLog#FILE}. Each robot's
 * folder then replays, plots and serves in the inspector as a run of one robot does; a team's
 * folder as a whole too ({@link TeamRuns}). Only reads, so the run is the same with or without it.
 */
public final class TeamTap implements Closeable {
    private final Map<String, RobotTap> robots = new LinkedHashMap<>();

    private TeamTap() {
    }

    /**
     * Taps {@code run}; call before it runs.
     *
     * @param inspector the inspector, or null
     * @param outDir    the team's folder, where each robot's step log goes, or null for none
     * @param experiment the experiment's name for the step logs' headers (e.g. team-delivery)
     */
    public static TeamTap attach(TeamLockstepRun run, Inspector inspector, Path outDir, String experiment, String agentFile)
            throws IOException {
        var tap = new TeamTap();
        SimWorld w = run.world();
        WorldSnapshot start = w.snapshot();
        for (String name : run.robots()) {
            Agent agent = run.mas().agent(name);
            StepLog.Writer log = null;
            if (outDir != null) {
                var header = new StepLog.Header(StepLog.FORMAT, experiment, w.name(), w.seed(), w.controlStep(), name,
                        agentFile, start, agent == null ? null : MindProbe.planTexts(agent));
                Path dir = Files.createDirectories(outDir.resolve(name));
                log = RobotTap.open(dir.resolve(StepLog.FILE), header, inspector, name);
            }
            tap.robots.put(name, new RobotTap(w, robot(w, name), agent, inspector, log));
        }
        if (inspector != null) {
            inspector.world(start);
            inspector.workspace(ArtifactsView.of(run.workspace()));
        }
        run.onAnswer((robot, data, commands) -> tap.robots.get(robot).afterStep(data, commands));
        return tap;
    }

    private static Robot robot(SimWorld w, String name) {
        return w.robots().stream().filter(r -> r.name().equals(name)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no robot " + name + " in the world"));
    }

    @Override
    public void close() throws IOException {
        IOException first = null;
        for (RobotTap r : robots.values()) {
            try {
                r.close();
            } catch (IOException e) {
                first = first == null ? e : first;
            }
        }
        if (first != null) {
            throw first;
        }
    }
}
