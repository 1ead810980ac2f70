package jacabot.sim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

class WorldFileReaderTest {
    static final String K = "\"robots\": [{\"name\": \"k\", \"model\": \"khepera\"}]";

    /** The world the README shows, every field of the format in it, loads as written there once its page-only comments go. */
    @Test
    void theReadmesExampleWorldLoads() throws Exception {
        String readme = java.nio.file.Files.readString(Path.of(System.getProperty("jacabot.rootDir", "."), "sim-world", "README.md"));
        int start = readme.indexOf("```json\n") + 8;
        String json = readme.substring(start, readme.indexOf("```", start)).replaceAll("(?m)\\s+//.*$", "");
        WorldSpec spec = WorldFileReader.parse(json, "sim-world/README.md");
        assertEquals(7, spec.events().size());
    }

    static Stream<Arguments> invalidWorlds() {
        return Stream.of(
                Arguments.of("{\"robots\": [{\"name\": \"r\", \"model\": \"pioneer\"}]}", "$.robots[0].model", "unknown robot model 'pioneer' (known: mybot, khepera)"),
                Arguments.of("{\"cylinders\": [{\"x\": 0.2, \"z\": 0}, {\"x\": 0.3, \"z\": 0, \"radius\": -0.01}]}", "$.cylinders[1].radius", "must be > 0, got -0.01"),
                Arguments.of("{\"boxes\": [{\"x\": 0.48, \"z\": 0, \"size\": 0.1}]}", "$.boxes[0]", "box 'box0' lies outside the arena"),
                Arguments.of("{\"boxes\": [{\"id\": \"b\", \"x\": 0.2, \"z\": 0, \"size\": 0.1}], \"cylinders\": [{\"x\": 0.25, \"z\": 0.05}]}", "$.cylinders[0]", "cylinder 'cylinder0' overlaps box 'b' at start"),
                Arguments.of("{\"boxes\": [{\"x\": 0.0, \"z\": 0, \"size\": 0.1}], " + K + "}", "$.robots[0]", "robot 'k' overlaps box 'box0' at start"),
                Arguments.of("{\"boxes\": [{\"x\": 0.2, \"z\": 0, \"size\": 0.1, \"colour\": \"red\"}]}", "$.boxes[0].colour", "unknown field"),
                Arguments.of("{\"robots\": [{\"name\": \"k\", \"model\": \"khepera\", \"x\": \"0.1\"}]}", "$.robots[0].x", "expected a number, got a string"),
                Arguments.of("{\"cylinders\": [{\"z\": 0.1}]}", "$.cylinders[0].x", "missing required field"),
                Arguments.of("{\"arena\": {\"width\": 1.0,}}", "$", "not valid JSON at line 1"),
                Arguments.of("{\"basicTimeStep\": 8, \"controlStep\": 30}", "$.controlStep", "must be a positive multiple of basicTimeStep (8 ms), got 30"),
                Arguments.of("{\"basicTimeStep\": 8.5}", "$.basicTimeStep", "expected an integer"),
                Arguments.of("{\"cylinders\": [{\"id\": \"c\", \"x\": 0.2, \"z\": 0}, {\"id\": \"c\", \"x\": 0.3, \"z\": 0}]}", "$.cylinders[1].id", "the name 'c' is already used by cylinder 'c'"),
                Arguments.of("{\"boxes\": [{\"x\": 0.2, \"z\": 0, \"size\": 0.1, \"color\": \"mauve\"}]}", "$.boxes[0].color", "not a colour: 'mauve'"),
                Arguments.of("{\"boxes\": [{\"x\": 0.2, \"z\": 0, \"size\": [0.1]}]}", "$.boxes[0].size", "expected [sizeX, sizeZ]"),
                Arguments.of("{\"robots\": [{\"name\": \"m\", \"model\": \"mybot\", \"battery\": 100}]}", "$.robots[0].battery", "model 'mybot' has no battery"),
                Arguments.of("{" + K + ", \"events\": [{\"at\": 1, \"do\": \"remove\", \"object\": \"ghost\"}]}", "$.events[0].object", "no box, cylinder or robot named 'ghost'"),
                Arguments.of("{" + K + ", \"events\": [{\"at\": 1, \"when\": {\"robot\": \"k\", \"near\": \"k\"}, \"do\": \"knock\", \"robot\": \"k\"}]}", "$.events[0]", "exactly one of \"at\""),
                Arguments.of("{" + K + ", \"events\": [{\"at\": 1, \"do\": \"explode\"}]}", "$.events[0].do", "unknown event action 'explode'"),
                Arguments.of("{\"robots\": [{\"name\": \"m\", \"model\": \"mybot\"}], \"events\": [{\"at\": 1, \"do\": \"knock\", \"robot\": \"m\"}]}", "$.events[0].robot", "has no gripper"),
                Arguments.of("{" + K + ", \"events\": [{\"at\": -1, \"do\": \"drain\", \"robot\": \"k\"}]}", "$.events[0].at", "must be >= 0"),
                Arguments.of("{" + K + ", \"events\": [{\"at\": 1, \"do\": \"move\", \"object\": \"k\", \"x\": 2, \"z\": 0}]}", "$.events[0]", "lies outside the arena"),
                Arguments.of("{\"storage\": {\"x\": 0.8, \"z\": 0}}", "$.storage", "lies outside the arena"),
                Arguments.of("[1, 2]", "$", "expected an object, got an array"),
                Arguments.of("", "$", "the file is empty"));
    }

    @ParameterizedTest
    @MethodSource("invalidWorlds")
    void invalidWorldsNameTheJsonPathAndTheProblem(String json, String path, String problem) {
        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldFileReader.parse(json, "bad.json"));
        assertEquals(path, e.jsonPath(), e.getMessage());
        assertTrue(e.problem().contains(problem), e.problem());
        assertEquals("bad.json: " + path + ": " + e.problem(), e.getMessage());
    }

    @Test
    void aMissingFileIsAWorldFileErrorToo() {
        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldFileReader.read(Path.of("no/such/world.json")));
        assertEquals("$", e.jsonPath());
        assertEquals("cannot read the world file (no such file)", e.problem());
    }

    @Test
    void defaultsFollowTheIssue() throws WorldFileException {
        WorldSpec s = WorldFileReader.parse("{}", "empty");
        assertEquals(8, s.basicTimeStep());
        assertEquals(40, s.controlStep());
        assertEquals(1.0, s.arena().width());
        assertTrue(s.sensorNoise());
    }

    @ParameterizedTest
    @ValueSource(strings = {"obstacle-avoidance", "object-picking", "navigation", "suspend-resume"})
    void theExperimentWorldsLoad(String name) throws WorldFileException {
        SimWorld w = SimWorld.load(TestWorlds.worldsDir().resolve(name + ".json"));
        assertEquals(name, w.name());
        assertEquals(40, w.controlStep());
        assertEquals(8, w.basicTimeStep());
        assertNotNull(w.robots().get(0));
        w.step();
    }

    @Test
    void theStorageAndChargerAreWhereAppendixBSays() throws WorldFileException {
        SimWorld w = SimWorld.load(TestWorlds.worldsDir().resolve("suspend-resume.json"));
        assertEquals(0.41, w.spec().storage().x());
        assertEquals(-0.41, w.spec().storage().z());
        assertEquals(-0.38, w.spec().charger().x());
        assertEquals(0.38, w.spec().charger().z());
    }
}
