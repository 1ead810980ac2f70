package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;

/**
 * {@link ArtifactId} and {@link AgentId} write out their equality and hash (the generated ones go
 * through method handles on every percept update): the same answers as records, and the same hash
 * values, so that a hashed collection of ids keeps the order it had.
 */
class IdentityTest {
    /** The records as the compiler makes them, for their generated methods. */
    private record GeneratedArtifactId(int id, String name, String type, String workspace, AgentId creator) {
    }

    private record GeneratedAgentId(String name) {
    }

    @Test
    void hashesAreTheGeneratedOnes() {
        for (AgentId creator : new AgentId[] {null, new AgentId("bob"), new AgentId("")}) {
            for (int id : new int[] {0, 1, 7, -3, Integer.MAX_VALUE}) {
                var a = new ArtifactId(id, "body", "jacabot.X", "main", creator);
                assertEquals(new GeneratedArtifactId(id, "body", "jacabot.X", "main", creator).hashCode(), a.hashCode());
            }
        }
        assertEquals(new GeneratedAgentId("robot").hashCode(), new AgentId("robot").hashCode());
    }

    @Test
    void equalityIsEveryComponents() {
        var bob = new AgentId("bob");
        var a = new ArtifactId(3, "c", "T", "w", bob);
        assertEquals(a, new ArtifactId(3, "c", "T", "w", new AgentId("bob")));
        assertNotEquals(a, new ArtifactId(4, "c", "T", "w", bob));
        assertNotEquals(a, new ArtifactId(3, "d", "T", "w", bob));
        assertNotEquals(a, new ArtifactId(3, "c", "U", "w", bob));
        assertNotEquals(a, new ArtifactId(3, "c", "T", "v", bob));
        assertNotEquals(a, new ArtifactId(3, "c", "T", "w", null));
        assertNotEquals(new ArtifactId(3, "c", "T", "w", null), a);
        assertEquals(new ArtifactId(3, "c", "T", "w", null), new ArtifactId(3, "c", "T", "w", null));
        assertNotEquals(new AgentId("bob"), new AgentId("alice"));
        assertNotEquals((Object) new AgentId("bob"), "bob");
    }
}
