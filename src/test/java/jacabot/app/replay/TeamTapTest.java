package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import jacabot.app.inspector.Inspector;
import jacabot.app.plot.RunPlots;
import jacabot.app.run.AgentSource;
import jacabot.app.run.TeamLockstepRun;
import jacabot.app.world.TeamWorld;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A team's run in the tools: every robot's step log in its own folder holds that robot's steps
 * (the commands its agent answered, step for step as its event log has them, and its agent's
 * mind), the inspector shows every robot's agent and the team's shared artifacts as each agent
 * perceives them, with their operations and who focuses on them, the team's plot draws every
 * robot, and the run is the same with the tap as without it.
 */
class TeamTapTest {
    static final double SECONDS = 2;

    /** Checks made at the end of the run, its workspace still open. */
    interface AtTheEnd {
        void check() throws Exception;
    }

    private static Map<String, List<String>> run(Path dir, Inspector inspector, AtTheEnd atTheEnd) throws Exception {
        WorldSpec spec = WorldFileReader.read(Path.of(System.getProperty("jacabot.rootDir", "."), "worlds/team-delivery.json"));
        SimWorld world = SimWorld.of(TeamWorld.firstRobots(spec, 2));
        AgentSource agent = AgentSource.resource("/asl/team-delivery.asl", "team-delivery.asl");
        try (var run = new TeamLockstepRun(world, agent, 7, new PrintStream(OutputStream.nullOutputStream()))) {
            TeamTap tap = dir == null ? null : TeamTap.attach(run, inspector, dir, "team-delivery", "team-delivery.asl");
            run.runFor(SECONDS);
            atTheEnd.check();
            if (tap != null) {
                tap.close();
            }
            Map<String, List<String>> logs = new LinkedHashMap<>();
            for (String r : run.robots()) {
                logs.put(r, List.copyOf(run.eventLog(r)));
            }
            return logs;
        }
    }

    @Test
    @Timeout(120)
    void everyRobotHasItsStepLogAndItsMindAndTheRunIsTheSame(@TempDir Path dir) throws Exception {
        Map<String, List<String>> plain = run(null, null, () -> {
        });
        Map<String, List<String>> tapped;
        var client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        try (Inspector inspector = Inspector.startOnFreePort()) {
            tapped = run(dir, inspector, () -> workspaceShown(client, inspector));
            assertEquals("[\"khepera1\",\"khepera2\"]", get(client, inspector.url("api/agents")));
            String artifacts = get(client, inspector.url("api/artifacts"));
            for (String shared : List.of("\"board\":{\"khepera1\"", "\"charger\":{\"khepera1\"", "\"khepera2\":[")) {
                assertTrue(artifacts.contains(shared), shared + " in " + artifacts);
            }
        }
        assertEquals(plain, tapped, "every robot's event log, with the tap and without");

        assertEquals(List.of(dir.resolve("khepera1"), dir.resolve("khepera2")), TeamRuns.robotDirs(dir));
        int steps = (int) Math.round(SECONDS * 1000 / 40);
        for (String robot : plain.keySet()) {
            Replay replay = Replay.open(dir.resolve(robot));
            assertEquals(robot, replay.header().robot());
            List<String> answered = plain.get(robot).stream().filter(l -> l.contains(" -> ")).toList();
            assertEquals(steps, replay.frames().size(), robot + ": a step per control step");
            assertEquals(steps, answered.size());
            boolean commanded = false;
            for (int i = 0; i < steps; i++) {
                Replay.Frame f = replay.frames().get(i);
                assertTrue(answered.get(i).endsWith(" -> " + f.commands()), robot + " step " + i + ": " + answered.get(i)
                        + " vs " + f.commands());
                commanded |= !f.commands().isEmpty();
            }
            assertTrue(commanded, robot + "'s agent commanded its robot");
            // its own agent's mind: the percepts of its own middleware artifact, not another robot's
            var artifacts = new TreeSet<String>();
            replay.frames().get(steps - 1).mind().beliefs().forEach(b -> b.annots().stream()
                    .filter(a -> a.startsWith("artifact_name(\"middleware_")).forEach(artifacts::add));
            assertEquals(Set.of("artifact_name(\"middleware_" + robot + "\")"), artifacts, robot + "'s mind");
        }
        var first = Replay.open(dir.resolve("khepera1")).frames();
        var second = Replay.open(dir.resolve("khepera2")).frames();
        assertTrue(first.get(0).body().x() != second.get(0).body().x() || first.get(0).body().z() != second.get(0).body().z(),
                "each log holds its own robot's body");

        RunPlots.writeTeam(dir, new PrintStream(OutputStream.nullOutputStream()));
        assertTrue(Files.size(dir.resolve("trajectory.png")) > 0, "the team's trajectories");
        assertTrue(Files.isRegularFile(dir.resolve("khepera2").resolve("speed.png")), "each robot's plots");
    }

    /** The live workspace: each shared artifact's operations and both agents focusing on it, not the workspace's own. */
    private static void workspaceShown(HttpClient client, Inspector inspector) throws Exception {
        JsonNode ws = new ObjectMapper().readTree(get(client, inspector.url("api/workspace")));
        JsonNode board = ws.path("board");
        assertEquals("jacabot.experiments.team.TaskBoard", board.path("type").asText(), ws.toString());
        assertTrue(board.path("operations").toString().contains("\"claim/3\""), board.toString());
        assertEquals(Set.of("khepera1", "khepera2"), names(board.path("focusedBy")), board.toString());
        assertEquals(Set.of("khepera1", "khepera2"), names(ws.path("charger").path("focusedBy")), ws.toString());
        assertEquals(Set.of("khepera2"), names(ws.path("middleware_khepera2").path("focusedBy")), ws.toString());
        assertTrue(ws.path("console").isMissingNode() && ws.path("workspace").isMissingNode(), ws.toString());
    }

    private static Set<String> names(JsonNode list) {
        var out = new TreeSet<String>();
        list.forEach(n -> out.add(n.asText()));
        return out;
    }

    private static String get(HttpClient c, String url) throws Exception {
        return c.send(HttpRequest.newBuilder(URI.create(url)).build(), HttpResponse.BodyHandlers.ofString()).body();
    }
}
