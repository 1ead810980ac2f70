package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.agent.syntax.Literal;
import jacabot.app.world.TeamWorld;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Tidy-up's agent is told when its task ends (the end of the run, whatever its duration), so its
 * recharge-trip skill makes no trip the battery does not need; an experiment whose recharge
 * episodes are the task itself is told nothing. Every agent of a team is told too (team-delivery:
 * its team-charger skill books no place at the charger either).
 */
class TaskEndTest {
    private static final double SECONDS = 2.5;

    @ParameterizedTest
    @EnumSource(value = Experiment.class, names = {"TIDY_UP", "SUSPEND_RESUME"})
    void theTaskEndsWithTheRunOnlyForTidyUp(Experiment e) throws Exception {
        SimWorld w = SimWorld.load(Path.of(System.getProperty("jacabot.rootDir", "."), e.worldFile()));
        try (var run = new LockstepRun(w, null, e, AgentSource.packaged(e), w.seed(),
                new PrintStream(OutputStream.nullOutputStream())).inMemory(true)) {
            run.runFor(SECONDS);
            List<String> taskEnd = run.mas().agent(RobotAgent.ALONE).beliefBase().beliefs().stream()
                    .filter(b -> b.functor().equals("taskEnd")).map(Literal::toString).toList();
            assertEquals(e == Experiment.TIDY_UP ? List.of("taskEnd(2500)[source(self)]") : List.of(), taskEnd);
        }
    }

    @Test
    void everyAgentOfATeamIsToldTheRunsEnd() throws Exception {
        SimWorld w = SimWorld.of(TeamWorld.firstRobots(WorldFileReader.read(
                Path.of(System.getProperty("jacabot.rootDir", "."), "worlds/team-delivery.json")), 2));
        try (var run = new TeamLockstepRun(w, AgentSource.resource("/asl/team-delivery.asl", "team-delivery.asl"), 7,
                new PrintStream(OutputStream.nullOutputStream()))) {
            run.runFor(SECONDS);
            for (String robot : run.robots()) {
                List<String> taskEnd = run.mas().agent(robot).beliefBase().beliefs().stream()
                        .filter(b -> b.functor().equals("taskEnd")).map(Literal::toString).toList();
                assertEquals(List.of("taskEnd(2500)[source(self)]"), taskEnd, robot);
            }
        }
    }
}
