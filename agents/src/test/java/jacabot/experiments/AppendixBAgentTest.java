package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Var;
import jacabot.agent.testing.TestAgent;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The Appendix B agent as published (our rewrite, agents/src/main/asl/as-published/suspend-resume.asl)
 * against a scripted middleware: its plans are selected as Chapter 4 describes. No simulator is
 * involved. (The default agent adds recovery plans, not in the thesis, and takes its landmarks from the world.)
 */
class AppendixBAgentTest {
    private static final Path AGENT = Path.of(System.getProperty("jacabot.projectDir", "."))
            .resolve("src/main/asl/as-published/suspend-resume.asl");
    private TestAgent robot;

    @BeforeEach
    void connect() {
        robot = TestAgent.fromFile("robot", AGENT);
        robot.outputs = AppendixBAgentTest::scriptedOutputs;
        robot.environment = a -> !a.action().functor().equals("lookupArtifact"); // nobody made it yet
        robot.cycles(200);
        assertTrue(robot.actionNames().get(0).startsWith("lookupArtifact(\"middleware\","), robot.actionNames().toString());
        assertTrue(robot.actionNames().get(1).matches("makeArtifact\\(\"middleware\",\"jacabot.experiments.SuspendResumeMiddleware\",\\[4444\\],(Id|_[0-9]+(Id)?)\\)"),
                robot.actionNames().toString());
        assertTrue(robot.actionNames().containsAll(List.of("focus(cobj_1)", "println(\"focus achieved\")", "accept")),
                robot.actionNames().toString());
        robot.advance(500, 200);
        assertFalse(robot.actionNames().contains("acquireData"), "not connected yet: it keeps waiting");
        robot.percept("connected(true)");
        robot.advance(500, 200);
        assertTrue(robot.actionNames().containsAll(List.of("deltaBased(false)", "setUpTargetPoint(0.41,0,-0.41)",
                "setThreshold(0.04)", "acquireData")), robot.actionNames().toString());
        int before = robot.actions.size();
        robot.cycles(50);
        String firstMove = robot.actionNames().get(robot.actions.size() - 1);
        assertTrue(List.of("forward", "turnLeft", "turnRight").contains(firstMove), "random motion starts: " + firstMove);
        assertTrue(robot.actions.size() > before - 1);
    }

    /** The middleware's answers: an artifact id, and the heading towards the target. */
    private static void scriptedOutputs(ActionExec a, Unifier u) {
        var act = a.action();
        if (act.functor().equals("makeArtifact") && act.arg(3) instanceof Var id) {
            u.bind(id, new ObjectTerm("cobj_1"));
        } else if (act.functor().equals("computeAngle") && act.arg(4) instanceof Var desired) {
            u.bind(desired, new NumberTerm(135));
        }
    }

    private void runFor(long ms) {
        for (long t = 0; t < ms; t += 10) {
            robot.advance(10, 500);
        }
    }

    @Test
    void anObstacleSuspendsRandomMotionUntilTheSensorsAreSafe() {
        robot.percept("delta(150)").percept("obstacle(true)");
        robot.cycles(100);
        assertTrue(robot.printed().contains("Obstacle: 150"), robot.printed().toString());
        runFor(100);
        List<String> acts = robot.actionNames();
        int stop = acts.lastIndexOf("stop");
        assertTrue(stop >= 0 && acts.subList(stop, acts.size()).containsAll(List.of("backward", "setSpeeds(50,-50)")),
                "turns away from a right-hand obstacle: " + acts);
        assertTrue(robot.believes("avoiding"));
        runFor(11_000);
        assertTrue(robot.printed().contains("Wait avoiding"), "random motion waits: " + robot.printed());
        int moves = robot.actions.size();
        robot.unpercept("obstacle(true)").percept("obstacle(false)");
        runFor(12_000);
        assertFalse(robot.believes("avoiding"));
        assertTrue(robot.actions.size() > moves, "random motion resumes");
    }

    /** A lateral cylinder's approach that times out after the battery ran low must not stop the trip to the charger. */
    @Test
    void aFailedApproachDoesNotStopTheTripToTheCharger() {
        robot.signal("cylinderLeft");
        robot.cycles(100);
        robot.signal("cylinderBeyond");
        robot.cycles(100);
        assertTrue(robot.actionNames().contains("setSpeeds(20,20)"), "approaches slowly: " + robot.actionNames());
        robot.percept("location(0.1,0,0.2)").percept("orientation(135)").percept("battery(470)");
        robot.signal("lowBattery");
        runFor(200);
        List<String> acts = robot.actionNames();
        assertEquals("forward", acts.get(acts.size() - 1), "heads for the charger: " + acts);
        int heading = acts.size();
        runFor(9_000);
        assertTrue(robot.printed().contains("Reach lateral cylinder failed."), robot.printed().toString());
        List<String> after = robot.actionNames().subList(heading, robot.actions.size());
        assertFalse(after.contains("stop"), "still on its way: " + after);
    }

    @Test
    void lowBatterySuspendsTheTaskGoesToTheChargerAndComesBack() {
        robot.percept("location(0.1,0,0.2)").percept("orientation(90)").percept("battery(470)");
        robot.signal("lowBattery");
        robot.cycles(200);
        assertTrue(robot.printed().contains("Battery low! Level: 470"), robot.printed().toString());
        List<String> acts = robot.actionNames();
        int mark = acts.indexOf("mark");
        assertTrue(mark >= 0, acts.toString());
        assertTrue(acts.subList(mark, acts.size()).containsAll(List.of("stop", "setUpTargetPoint(-0.38,0,0.38)")), acts.toString());
        assertTrue(acts.stream().anyMatch(a -> a.startsWith("computeAngle(0.1,0.2,-0.38,0.38,")), acts.toString());
        assertTrue(robot.believes("charging"));
        assertTrue(robot.believes("desired(135)"));
        runFor(200);
        assertTrue(robot.actionNames().contains("setSpeeds(25,-10)"), "balances towards the charger: " + robot.actionNames());
        runFor(11_000);
        assertTrue(robot.printed().contains("wait recharging"), "random motion is suspended: " + robot.printed());

        robot.signal("targetReached");
        runFor(3_100);
        assertFalse(robot.printed().contains("RECHARGED"), "waits for the charged signal, not 3 s: " + robot.printed());
        assertTrue(robot.actionNames().contains("stopAcquireDistance"), "ignores walls at the charger");
        robot.signal("charged");
        runFor(100);
        assertTrue(robot.printed().contains("RECHARGED"), robot.printed().toString());
        assertTrue(robot.actionNames().contains("restartAcquireDistance"));
        assertTrue(robot.actionNames().contains("setUpTargetPoint(0.1,0,0.2)"), "heads back to the marked point");

        robot.signal("targetReached");
        runFor(200);
        assertTrue(robot.printed().contains("Previous pt reached"), robot.printed().toString());
        assertTrue(robot.printed().contains("Restoring"));
        assertTrue(robot.believes("desired(90)"), "restores the marked orientation");
        robot.unpercept("orientation(90)").percept("orientation(90.2)");
        runFor(700);
        assertTrue(robot.printed().contains("Restored"), robot.printed().toString());
        assertFalse(robot.believes("charging"));
        runFor(100);
        assertTrue(robot.printed().contains("after recharging"), "random motion resumes: " + robot.printed());
    }

    @Test
    void aCylinderAheadIsPickedAndDelivered() {
        robot.percept("location(0.1,0,0.2)").percept("orientation(0)");
        robot.signal("cylinderDetected");
        robot.cycles(100);
        assertTrue(robot.printed().contains("Cylinder detected"));
        assertTrue(robot.actionNames().contains("catching"));
        robot.percept("caught(true)");
        robot.cycles(100);
        assertTrue(robot.actionNames().contains("arm_up"), robot.actionNames().toString());
        robot.percept("picked(true)");
        runFor(100);
        assertTrue(robot.actionNames().contains("println(\"Cylinder picked up\")"), robot.actionNames().toString());
        assertTrue(robot.believes("delivering"));
        assertTrue(robot.believes("desired(135)"), "heads for the storage point");
    }
}
