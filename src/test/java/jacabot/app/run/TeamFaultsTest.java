package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.experiments.team.TaskBoard;
import jacabot.robot.link.LinkSecret;
import java.io.OutputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Faults of a team (thesis Chapter 6): the first agent that holds a claim on the task board after
 * 5 s dies (its reasoning throws at its next plan selection). Its robot stops within 200 ms of simulated time (its link ends, its
 * controller's fail-safe stops the wheels), the other robot goes on to the end, and the board frees
 * the dead agent's claims and the charger queue its place: in one process and in two.
 */
class TeamFaultsTest {
    private static final double SECONDS = 12;
    private static final long DIE_AFTER_MS = 5000;
    private static final List<String> TEAM = List.of("khepera1", "khepera2");
    private static final Pattern READING = Pattern.compile("step (\\d+) t=(\\d+) .*WHEEL_SPEEDS=\\[([-0-9.E]+),([-0-9.E]+)\\].*");

    /** When and how the victim died, and what the board and queue showed after. */
    private static final class Death {
        volatile String victim;
        volatile long atMs = -1;
        volatile long wallNanos;
        volatile int claimsHeld;
        volatile int claimsAfter = -1;
        volatile boolean queuedAfter;
    }

    /**
     * Makes an agent's reasoning throw at its first plan selection once it holds a claim, the first
     * agent to hold one. Armed after the first step: the run's failure watch has then seen each
     * agent's plan for its initial goal.
     */
    private static Death arm(TeamLockstepRun run) {
        Death d = new Death();
        run.onStep(t -> {
            if (t == 0) {
                for (String agent : TEAM) {
                    run.mas().agent(agent).setPlanListener((event, plan) -> die(run, d, agent));
                }
            }
            if (d.atMs >= 0 && d.claimsAfter < 0) { // the step the agent died in, every robot answered
                d.claimsAfter = (int) run.board().claims().stream().map(TaskBoard.Held::agent).filter(d.victim::equals).count();
                d.queuedAfter = run.charger().queued().contains(d.victim);
            }
        });
        return d;
    }

    private static void die(TeamLockstepRun run, Death d, String agent) {
        long held = run.board().claims().stream().filter(h -> h.agent().equals(agent)).count();
        if (held > 0 && d.atMs < 0 && run.mas().clock().millis() >= DIE_AFTER_MS) {
            d.victim = agent;
            d.claimsHeld = (int) held;
            d.atMs = run.mas().clock().millis();
            d.wallNanos = System.nanoTime();
            throw new IllegalStateException("simulated: the agent's interpreter fails");
        }
    }

    /** Checks the victim's robot against its controller's event log, and {@return the simulated ms from death to standing still} */
    private static long stopDelay(List<String> events, Death d) {
        boolean movingAtDeath = false;
        for (String e : events) {
            Matcher m = READING.matcher(e);
            if (!m.matches()) {
                continue;
            }
            long t = Long.parseLong(m.group(2));
            boolean still = Double.parseDouble(m.group(3)) == 0 && Double.parseDouble(m.group(4)) == 0;
            if (t == d.atMs) {
                movingAtDeath = !still;
            }
            if (t > d.atMs && still) {
                assertTrue(movingAtDeath, "the robot was moving when its agent died");
                return t - d.atMs;
            }
        }
        throw new AssertionError("the robot of the dead agent never stood still after t=" + d.atMs);
    }

    /** {@return the robot whose agent lived} */
    private static String survivor(Death d) {
        return TEAM.stream().filter(r -> !r.equals(d.victim)).findFirst().orElseThrow();
    }

    private static void assertTheTeamWentOn(Death d, TeamLockstepRun run, List<String> victimEvents, List<String> survivorEvents,
            List<String> survivorAgentLog) {
        String survivor = survivor(d);
        long delay = stopDelay(victimEvents, d);
        System.out.println("TeamFaultsTest: " + d.victim + " died at t=" + d.atMs + " ms holding " + d.claimsHeld
                + " claim(s); its robot stood still " + delay + " ms of simulated time later");
        assertTrue(delay <= 200, d.victim + " stood still " + delay + " ms of simulated time after its agent died");
        assertTrue(victimEvents.stream().anyMatch(l -> l.contains(" fail-safe the link to the middleware dropped")), "its fail-safe tripped");
        assertTrue(d.claimsHeld > 0 && d.claimsAfter == 0, "the board freed its claims: " + d.claimsHeld + " then " + d.claimsAfter);
        assertTrue(!d.queuedAfter, "not in the charger's queue");
        assertEquals(List.of(d.victim), run.departures().stream().map(s -> s.split(" ")[0]).toList());
        assertEquals(Math.round(SECONDS * 1000 / 40), survivorAgentLog.size(), survivor + "'s agent answered every step");
        long lastApply = survivorEvents.stream().filter(l -> l.contains(" apply ")).mapToLong(l -> Long.parseLong(l.split(" ")[1]))
                .max().orElse(-1);
        assertTrue(lastApply * 40 > d.atMs, survivor + " was still driven after " + d.victim + " died (last command at step " + lastApply + ")");
        assertTrue(run.agentFailure().isEmpty(), () -> "the team's run went on: " + run.agentFailure());
    }

    @Test
    void inOneProcessADeadAgentLeavesTheTeamAndItsRobotStops() throws Exception {
        try (var run = new TeamLockstepRun(TeamControllerSide.world(2), TeamTwoProcessTest.AGENT, 7,
                new PrintStream(OutputStream.nullOutputStream()))) {
            Death d = arm(run);
            run.runFor(SECONDS);
            assertTrue(d.atMs > 0, "an agent claimed a cylinder, and then died");
            assertTheTeamWentOn(d, run, run.controllerLog(d.victim), run.controllerLog(survivor(d)), run.agentLog(survivor(d)));
        }
    }

    @Test
    void inTwoProcessesTheDeadAgentsLinkEndsAndTheControllersStopWaitingForIt() throws Exception {
        LinkSecret secret = LinkSecret.random();
        LinkSecret.useInThisProcess(secret);
        try (var run = new TeamLockstepRun(TeamControllerSide.world(2), TeamTwoProcessTest.AGENT, 7,
                new PrintStream(OutputStream.nullOutputStream())).remoteController(true)) {
            Death d = arm(run);
            try (var controllers = TeamControllerSide.against(run, secret, SECONDS)) {
                assertNull(controllers.joinBoth());
                assertTrue(d.atMs > 0, "an agent claimed a cylinder, and then died");
                assertTheTeamWentOn(d, run, controllers.events.get(d.victim), controllers.events.get(survivor(d)), run.agentLog(survivor(d)));
                long wallMs = TimeUnit.NANOSECONDS.toMillis(controllers.failSafeNanos.get(d.victim) - d.wallNanos);
                // the world waits for the answers in lockstep, so the simulated delay above is what the robot drove;
                // the wall clock is a figure of the machine's load
                System.out.println("TeamFaultsTest: the controllers' fail-safe stopped " + d.victim + " " + wallMs
                        + " ms (wall clock) after its agent died in the agents' process");
            }
        } finally {
            LinkSecret.resetUserDefault();
        }
    }
}
