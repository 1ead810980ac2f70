package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.agent.syntax.Literal;
import jacabot.app.sweep.EndState;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.WorldSpec;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A cylinder that lies in the storage area when the run starts counts as stored for tidy-up's success
 * criterion (its end state), and the agent is told so ({@code stored(K)}, in place of its delivery
 * skill's {@code stored(0)}): before, it searched for that cylinder to the run's end and never parked.
 */
class StoredAtStartTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void aCylinderInTheStorageAreaAtTheStartCountsAsStoredForTheCriterionAndTheAgent() throws Exception {
        WorldSpec w = withFirstCylinderStored(WorldFileReader.read(ROOT.resolve(Experiment.TIDY_UP.worldFile())));
        assertEquals(1, WorldBeliefs.storedAtStart(w));
        SimWorld world = SimWorld.of(w);
        assertEquals(1, EndState.of(world.snapshot(), Experiment.TIDY_UP.robot()).stored());
        try (var run = new LockstepRun(world, null, Experiment.TIDY_UP, AgentSource.packaged(Experiment.TIDY_UP), w.seed(),
                new PrintStream(OutputStream.nullOutputStream())).inMemory(true)) {
            run.runFor(0.5);
            List<String> stored = run.mas().agent(RobotAgent.ALONE).beliefBase().beliefs().stream()
                    .filter(b -> b.functor().equals("stored")).map(Literal::toString).toList();
            assertEquals(List.of("stored(1)"), stored.stream().map(s -> s.replaceAll("\\[.*", "")).toList());
        }
    }

    @Test
    void aWorldWithNoCylinderInTheStorageAreaTellsTheAgentNothingMore() throws Exception {
        WorldSpec w = WorldFileReader.read(ROOT.resolve(Experiment.TIDY_UP.worldFile()));
        assertEquals(0, WorldBeliefs.storedAtStart(w));
        assertEquals(List.of(), WorldBeliefs.of(w, Experiment.TIDY_UP).stream()
                .filter(b -> b.functor().equals("stored")).toList());
    }

    private static WorldSpec withFirstCylinderStored(WorldSpec w) {
        var cylinders = new ArrayList<>(w.cylinders());
        CylinderSpec c = cylinders.get(0);
        cylinders.set(0, new CylinderSpec(c.id(), w.storage().x(), w.storage().z(), c.radius(), c.height(), c.mass(), c.color()));
        return new WorldSpec(w.name(), w.arena(), w.basicTimeStep(), w.controlStep(), w.seed(), w.sensorNoise(), w.walls(),
                w.boxes(), cylinders, w.storage(), w.charger(), w.robots(), w.events());
    }
}
