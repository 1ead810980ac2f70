package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.world.TeamWorld;
import jacabot.experiments.team.TaskBoard;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * A team of two agents in lockstep in one process (team-delivery, thesis Chapter 6): both agents
 * run, each on its own robot through its own middleware artifact, and the run is a pure function of
 * world and seed (every robot's event log the same to the byte twice); the task board never holds
 * two agents' claims on one place.
 */
class TeamLockstepRunTest {
    private static final double SECONDS = 15;

    private record Run(Map<String, List<String>> logs, String console, List<String> boardViolations, int claimsSeen) {
    }

    private static Run run() throws Exception {
        WorldSpec spec = WorldFileReader.read(Path.of(System.getProperty("jacabot.rootDir", "."), "worlds/team-delivery.json"));
        SimWorld world = SimWorld.of(TeamWorld.firstRobots(spec, 2));
        var out = new ByteArrayOutputStream();
        var console = new PrintStream(out, true, StandardCharsets.UTF_8);
        AgentSource agent = AgentSource.resource("/asl/team-delivery.asl", "team-delivery.asl");
        List<String> violations = new ArrayList<>();
        int[] claims = {0};
        try (var run = new TeamLockstepRun(world, agent, 7, console)) {
            run.onStep(t -> {
                List<TaskBoard.Held> held = run.board().claims();
                claims[0] = Math.max(claims[0], held.size());
                for (TaskBoard.Held a : held) {
                    for (TaskBoard.Held b : held) {
                        if (!a.agent().equals(b.agent()) && Math.hypot(a.x() - b.x(), a.z() - b.z()) < TeamLockstepRun.CLAIM_RADIUS) {
                            violations.add("t=" + t + " " + a + " and " + b);
                        }
                    }
                }
            });
            run.runFor(SECONDS);
            assertTrue(run.agentFailure().isEmpty(), () -> "no agent failed: " + run.agentFailure());
            Map<String, List<String>> logs = new LinkedHashMap<>();
            for (String r : run.robots()) {
                logs.put(r, run.eventLog(r));
            }
            return new Run(logs, out.toString(StandardCharsets.UTF_8), violations, claims[0]);
        }
    }

    @Test
    void twoAgentsRunTheirRobotsInLockstepAndTheRunIsTheSameTwice() throws Exception {
        Run first = run();
        assertEquals(List.of("khepera1", "khepera2"), List.copyOf(first.logs().keySet()));
        int steps = (int) Math.round(SECONDS * 1000 / 40);
        for (var e : first.logs().entrySet()) {
            List<String> agentSide = e.getValue().stream().filter(l -> l.contains(" -> ")).toList();
            assertEquals(steps, agentSide.size(), e.getKey() + " answered every step");
            assertTrue(agentSide.stream().anyMatch(l -> !l.endsWith(" -> []")), e.getKey() + "'s agent commanded its robot");
            assertTrue(e.getValue().stream().anyMatch(l -> l.contains(" apply ")), e.getKey() + "'s controller applied commands");
        }
        assertTrue(first.console().contains("[khepera1] focus achieved") && first.console().contains("[khepera2] focus achieved"),
                first.console());
        assertTrue(first.boardViolations().isEmpty(), () -> "two claimers on one place: " + first.boardViolations());
        Run second = run();
        for (String robot : first.logs().keySet()) {
            assertEquals(String.join("\n", first.logs().get(robot)), String.join("\n", second.logs().get(robot)),
                    robot + "'s event log, to the byte");
        }
        assertEquals(first.console(), second.console());
    }
}
