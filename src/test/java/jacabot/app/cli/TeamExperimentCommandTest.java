package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jacabot experiment team-delivery}: the team's own command behind the experiment's name. */
class TeamExperimentCommandTest {
    @Test
    void aShortTeamRunPrintsAndWritesASummaryPerRobotAndForTheTeam(@TempDir Path dir) throws Exception {
        String[] r = CliRun.run("experiment", "team-delivery", "--robots", "2", "--duration", "3s", "--out", dir.toString());
        assertEquals("0", r[0], r[2]);
        String out = r[1];
        assertTrue(out.contains("[khepera1] picks ") && out.contains("[khepera2] picks "), out);
        assertTrue(out.contains("team: 0 deliveries of 12 cylinders in 3 s"), out);
        assertTrue(out.contains("criteria: not met"), out);
        for (String robot : new String[] {"khepera1", "khepera2"}) {
            assertTrue(Files.readString(dir.resolve(robot).resolve("summary.json")).contains("\"robot\" : \"" + robot + "\""));
            assertTrue(Files.exists(dir.resolve(robot).resolve("event-log.txt")));
            assertTrue(Files.size(dir.resolve(robot).resolve("steps.jsonl.gz")) > 0, robot + "'s step log");
        }
        assertTrue(Files.readString(dir.resolve("summary.txt")).startsWith("team-delivery, 2 robots, seed 21"));
        assertTrue(Files.size(dir.resolve("trajectory.png")) > 0, "every robot's trajectory");
        // the team's console: every agent's lines, named, at their control step's simulated time, in the order printed
        List<String> console = Files.readAllLines(dir.resolve("console.txt"));
        for (String l : console) {
            assertTrue(l.matches("t=\\d+\\.\\d{3} \\[\\w+\\] .*"), l);
            long t = Math.round(Double.parseDouble(l.substring(2, l.indexOf(' '))) * 1000);
            assertTrue(t % 40 == 0 && t <= 3000, l);
        }
        assertTrue(console.stream().anyMatch(l -> l.contains(" [khepera1] ")) && console.stream().anyMatch(l -> l.contains(" [khepera2] ")),
                console.toString());
        List<String> texts = console.stream().map(l -> l.substring(l.indexOf(' ') + 1)).toList();
        List<String> printed = out.lines().filter(l -> l.startsWith("[khepera") && !l.matches("\\[\\w+\\] picks \\d+, deliveries .*"))
                .toList(); // the agents' lines, not the summaries per robot
        assertTrue(printed.size() >= 2, out);
        int at = 0; // the printed lines (repeats folded) in the file, in order
        for (String p : printed) {
            while (at < texts.size() && !texts.get(at).equals(p)) {
                at++;
            }
            assertTrue(at < texts.size(), "printed, in console.txt in order: " + p + "\n" + console);
        }
        try (ServedReplay served = ServedReplay.start(dir)) { // the team's page serves it
            var client = HttpClient.newHttpClient();
            String answer = client.send(HttpRequest.newBuilder(URI.create(served.address().toString()
                    .replace("/?", "/api/console?from=0&to=3000&"))).build(), HttpResponse.BodyHandlers.ofString()).body();
            assertEquals(console.size(), new ObjectMapper().readTree(answer).get("lines").size(), answer);
        }

        // the team's folder in the tools: plotted again, one robot replayed, the whole team only in the inspector
        Files.delete(dir.resolve("trajectory.png"));
        String[] plot = CliRun.run("plot", dir.toString());
        assertEquals("0", plot[0], plot[2]);
        assertTrue(Files.exists(dir.resolve("trajectory.png")) && Files.exists(dir.resolve("khepera2").resolve("speed.png")), plot[1]);
        String[] one = CliRun.run("replay", dir.resolve("khepera2").toString(), "--headless");
        assertEquals("0", one[0], one[2]);
        assertTrue(one[1].contains("robot khepera2"), one[1]);
        String[] all = CliRun.run("replay", dir.toString(), "--headless");
        assertEquals("2", all[0], all[2]);
        assertTrue(all[2].contains("is a team's run") && all[2].contains("--headless --inspector"), all[2]);
    }

    @Test
    void theAgentsSideOfTwoProcessesLeavesTheOutputsToTheControllers() {
        String[] r = CliRun.run("experiment", "team-delivery", "--robots", "2", "--remote-controller", "--link-log");
        assertEquals("2", r[0], r[1] + r[2]);
        assertTrue(r[2].contains("--link-log goes with the controllers' process"), r[2]);
        r = CliRun.run("experiment", "team-delivery", "--robots", "4", "--remote-controller", "--port", "65534");
        assertEquals("2", r[0], r[1] + r[2]);
        assertTrue(r[2].contains("--port must leave 4 ports in 1..65535"), r[2]);
    }

    @Test
    void benchSimComparesATeamWithOneRobotInTheSameRun() {
        String[] r = CliRun.run("bench", "sim", "--robots", "2", "--duration", "2s", "--warmup", "0", "--runs", "1");
        assertEquals("0", r[0], r[2]);
        assertTrue(r[1].contains("\n| 1 | ") && r[1].contains("\n| 2 | "), r[1]);
        assertTrue(r[1].matches("(?s).*2 robots cost \\d+\\.\\d\\dx one robot per simulated second.*"), r[1]);
        assertEquals("2", CliRun.run("bench", "sim", "--robots", "5")[0]);
    }

    @Test
    void aWorldWithoutEnoughRobotsIsOneLineAndExitTwo() {
        String[] r = CliRun.run("experiment", "team-delivery", "--robots", "5", "--duration", "1s");
        assertEquals("2", r[0], r[1] + r[2]);
        assertTrue(r[2].strip().endsWith("$.robots: the team-delivery experiment with 5 robots needs as many; the world has 4"), r[2]);
        assertEquals(1, r[2].strip().lines().count(), r[2]);
    }

    @Test
    void theOtherExperimentsKeepTheirCommand() {
        String[] r = CliRun.run("experiment", "navigation", "--robots", "2");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("Unknown options: '--robots'"), r[2]);
    }
}
