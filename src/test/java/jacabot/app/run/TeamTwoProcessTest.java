package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.LinkSecret;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A team in two processes (thesis Chapter 6): the agents' side ({@link TeamLockstepRun#remoteController})
 * with one link per robot and the barrier, the controllers' side one {@code TeamLockstep} over TCP, as
 * {@code jacabot controller --lockstep --world FILE} runs it. The same team world and seed give every
 * robot's event log, the controller's and the agent side's, and the agents' console, to the byte of the
 * one-process run.
 */
class TeamTwoProcessTest {
    static final double SECONDS = 8;
    static final AgentSource AGENT = AgentSource.resource("/asl/team-delivery.asl", "team-delivery.asl");

    @Test
    void theTeamInTwoProcessesIsTheOneProcessRun() throws Exception {
        var oneOut = new ByteArrayOutputStream();
        TeamLockstepRun one = new TeamLockstepRun(TeamControllerSide.world(2), AGENT, 7,
                new PrintStream(oneOut, true, StandardCharsets.UTF_8));
        one.runFor(SECONDS);
        one.close();

        LinkSecret secret = LinkSecret.random();
        LinkSecret.useInThisProcess(secret);
        var twoOut = new ByteArrayOutputStream();
        try (TeamLockstepRun two = new TeamLockstepRun(TeamControllerSide.world(2), AGENT, 7,
                new PrintStream(twoOut, true, StandardCharsets.UTF_8)).remoteController(true)) {
            try (var controllers = TeamControllerSide.against(two, secret, SECONDS)) {
                assertNull(controllers.joinBoth());
                for (String robot : one.robots()) {
                    List<String> controllerLog = controllers.events.get(robot);
                    assertEquals(String.join("\n", one.controllerLog(robot)), String.join("\n", controllerLog),
                            robot + "'s controller event log");
                    assertEquals(String.join("\n", one.agentLog(robot)), String.join("\n", two.agentLog(robot)),
                            robot + "'s agent side's event log");
                    assertEquals(Math.round(SECONDS * 1000 / 40), two.agentLog(robot).size(), robot + " answered every step");
                    assertTrue(controllerLog.stream().anyMatch(l -> l.contains(" apply ")), robot + "'s agent drove");
                }
                assertEquals(oneOut.toString(StandardCharsets.UTF_8), twoOut.toString(StandardCharsets.UTF_8), "the agents' console");
                assertEquals(0, two.world().timeMs(), "the agents' world is not stepped");
            }
        } finally {
            LinkSecret.resetUserDefault();
        }
    }
}
