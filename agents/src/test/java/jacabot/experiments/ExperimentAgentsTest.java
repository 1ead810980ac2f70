package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Var;
import jacabot.agent.testing.TestAgent;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The four experiment agents parse, and experiments 1 and 2 react as Chapter 4 describes. */
class ExperimentAgentsTest {
    private static final Path ASL = Path.of(System.getProperty("jacabot.projectDir", ".")).resolve("src/main/asl");

    @Test
    void everyExperimentAgentParses() throws Exception {
        for (String name : List.of("obstacle-avoidance", "object-picking", "navigation", "suspend-resume")) {
            var program = new AslParser().parseFile(ASL.resolve(name + ".asl"));
            assertTrue(program.plans().size() >= 10, name + " has its plans");
            assertEquals(1, program.goals().size(), name + " starts with !start");
        }
    }

    private static TestAgent connected(String experiment) {
        var robot = TestAgent.fromFile("robot", ASL.resolve(experiment + ".asl"));
        robot.outputs = (ActionExec a, Unifier u) -> {
            if (a.action().functor().equals("makeArtifact") && a.action().arg(3) instanceof Var id) {
                u.bind(id, new ObjectTerm("cobj_1"));
            }
        };
        robot.environment = a -> !a.action().functor().equals("lookupArtifact");
        robot.cycles(100);
        robot.percept("connected(true)");
        robot.advance(100, 200);
        assertTrue(robot.actionNames().contains("acquireData"), robot.actionNames().toString());
        return robot;
    }

    @Test
    void avoidanceTurnsAwayFromTheObstaclesSideAndSuspendsRandomMotion() {
        var robot = connected("obstacle-avoidance");
        robot.percept("delta(-150)").percept("obstacle(true)");
        robot.cycles(50);
        robot.advance(50, 100);
        assertTrue(robot.actionNames().contains("println(\"obstacle: \",-150)"), robot.actionNames().toString());
        assertTrue(robot.actionNames().contains("setSpeeds(-50,50)"), "turns left, away from the right... " + robot.actionNames());
        assertTrue(robot.believes("avoiding"));
        robot.unpercept("obstacle(true)").percept("obstacle(false)");
        robot.cycles(50);
        assertTrue(!robot.believes("avoiding"));
    }

    @Test
    void aCentralObstacleMakesItBackOffAndTurnAround() {
        var robot = connected("obstacle-avoidance");
        robot.percept("delta(0)").percept("obstacle(true)");
        robot.cycles(50);
        robot.advance(50, 100);
        List<String> acts = robot.actionNames();
        int backward = acts.indexOf("backward");
        assertTrue(backward > 0 && acts.get(backward + 1).equals("turnAround"), acts.toString());
    }

    @Test
    void pickingTimesOutWhenTheCylinderMovesAwayAndResumes() {
        var robot = connected("object-picking");
        robot.signal("cylinderDetected");
        robot.cycles(50);
        assertTrue(robot.actionNames().contains("catching"));
        assertTrue(robot.believes("picking"));
        for (int i = 0; i < 60; i++) {
            robot.advance(100, 200);
        }
        assertTrue(robot.printed().contains("Cylinder not found"), robot.printed().toString());
        List<String> acts = robot.actionNames();
        assertTrue(acts.containsAll(List.of("open_grip", "turnAround")), acts.toString());
        robot.advance(2000, 200);
        assertTrue(!robot.believes("picking"), "random motion resumes");
    }

    @Test
    void aFallenCylinderStopsEverything() {
        var robot = connected("object-picking");
        robot.percept("picked(true)");
        robot.signal("fallen");
        robot.cycles(50);
        assertTrue(robot.printed().contains("Cylinder has fallen. Anybody retrieve it"), robot.printed().toString());
        List<String> acts = robot.actionNames();
        assertEquals(List.of("stopAcquire", "stop"), acts.subList(acts.size() - 2, acts.size()));
        int before = acts.size();
        robot.advance(20_000, 500);
        assertEquals(before, robot.actions.size(), "nothing runs after the fall");
    }
}
