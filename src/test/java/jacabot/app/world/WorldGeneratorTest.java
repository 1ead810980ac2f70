package jacabot.app.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.EventSpec;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import org.junit.jupiter.api.Test;

class WorldGeneratorTest {
    @Test
    void sameSeedSameTextOtherSeedOtherWorld() {
        for (Experiment e : Experiment.values()) {
            String a = new WorldGenerator(e, 7).generate().json();
            assertEquals(a, new WorldGenerator(e, 7).generate().json(), e.id());
            assertNotEquals(a, new WorldGenerator(e, 8).generate().json(), e.id());
        }
    }

    /** The loader already rejects overlaps and objects outside the arena; here what it does not check. */
    @Test
    void worldsFitTheirExperiment() {
        for (Experiment e : Experiment.values()) {
            for (long seed = 1; seed <= 40; seed++) {
                WorldSpec w = new WorldGenerator(e, seed).generate().spec();
                String where = e.id() + " seed " + seed;
                assertTrue(w.arena().width() >= 1 && w.arena().width() <= 3, where);
                assertTrue(w.arena().depth() >= 1 && w.arena().depth() <= 3, where);
                assertEquals(1, w.robots().size(), where);
                RobotSpec r = w.robots().get(0);
                assertEquals(e.robot(), r.name(), where);
                assertEquals(seed, w.seed(), where);
                switch (e) {
                    case OBSTACLE_AVOIDANCE -> assertTrue(w.cylinders().isEmpty(), where);
                    case OBJECT_PICKING -> assertTrue(w.cylinders().size() >= 1, where);
                    default -> assertTrue(w.cylinders().size() >= 2, where);
                }
                boolean storage = e == Experiment.NAVIGATION || e == Experiment.SUSPEND_RESUME || e == Experiment.TIDY_UP;
                assertEquals(storage, w.storage() != null, where);
                assertEquals(e == Experiment.SUSPEND_RESUME || e == Experiment.TIDY_UP, w.charger() != null, where);
                for (AreaSpec a : new AreaSpec[] {w.storage(), w.charger()}) {
                    if (a == null) {
                        continue;
                    }
                    // in a corner or along a wall
                    double toWall = Math.min(w.arena().halfWidth() - Math.abs(a.x()), w.arena().halfDepth() - Math.abs(a.z()));
                    assertTrue(toWall < a.radius() + 0.05, where + ": area " + a);
                    assertTrue(Math.hypot(r.x() - a.x(), r.z() - a.z()) > a.radius() + 0.03, where + ": robot starts off the area");
                    for (BoxSpec b : w.boxes()) {
                        assertTrue(Math.hypot(b.x() - a.x(), b.z() - a.z()) > a.radius() + 0.06, where + ": box near area");
                    }
                    for (CylinderSpec c : w.cylinders()) {
                        // the success criterion's test (tidy-up: a cylinder there would count as stored at the start)
                        assertTrue(!a.contains(c.x(), c.z()), where + ": cylinder in an area");
                    }
                }
                if (w.storage() != null && w.charger() != null) {
                    assertTrue(Math.hypot(w.storage().x() - w.charger().x(), w.storage().z() - w.charger().z()) >= 0.5, where);
                }
            }
        }
    }

    @Test
    void densityVariesAndFaultsAppear() {
        int fewest = Integer.MAX_VALUE, most = 0, faults = 0, nearFaults = 0;
        for (long seed = 1; seed <= 30; seed++) {
            WorldSpec w = new WorldGenerator(Experiment.SUSPEND_RESUME, seed).generate().spec();
            double perSquareMetre = w.boxes().size() / (w.arena().width() * w.arena().depth());
            fewest = Math.min(fewest, (int) perSquareMetre);
            most = Math.max(most, (int) perSquareMetre);
            faults += w.events().size();
            nearFaults += (int) w.events().stream().filter(ev -> ev.trigger() instanceof EventSpec.Near).count();
        }
        assertTrue(most >= 2 * Math.max(1, fewest), "sparse to dense: " + fewest + ".." + most + " boxes per m²");
        assertTrue(faults > 10 && nearFaults > 0, faults + " faults, " + nearFaults + " during a grip");
        assertNull(new WorldGenerator(Experiment.OBSTACLE_AVOIDANCE, 1).generate().spec().storage());
        assertNotNull(new WorldGenerator(Experiment.NAVIGATION, 1).maxSide(1).generate().spec().storage());
    }

    /** Seeds k and k+1 once shared their draws, shifted by one: world k+1's width was world k's depth. */
    @Test
    void consecutiveSeedsAreIndependent() {
        int shifted = 0;
        WorldSpec previous = new WorldGenerator(Experiment.NAVIGATION, 1).generate().spec();
        for (long seed = 2; seed <= 30; seed++) {
            WorldSpec w = new WorldGenerator(Experiment.NAVIGATION, seed).generate().spec();
            if (w.arena().width() == previous.arena().depth()) {
                shifted++;
            }
            previous = w;
        }
        assertTrue(shifted <= 2, shifted + " of 29 worlds have the previous seed's depth as width");
    }

    /** A team's world: N Kheperas apart, about a dozen cylinders, a storage point and a charger; teams of 1 to 4 share a layout. */
    @Test
    void teamWorldsHoldTheTeamApartAndShareALayout() {
        double apart = 2 * jacabot.sim.robot.RobotModel.KHEPERA.radius() + WorldGenerator.MIN_GAP;
        for (long seed = 1; seed <= 30; seed++) {
            WorldSpec one = WorldGenerator.team(1, seed).generate().spec();
            for (int n : new int[] {1, 2, 3, 4, 8}) {
                WorldSpec w = WorldGenerator.team(n, seed).generate().spec();
                String where = "team of " + n + ", seed " + seed;
                assertEquals(n, w.robots().size(), where);
                for (int i = 0; i < n; i++) {
                    RobotSpec r = w.robots().get(i);
                    assertEquals("khepera" + (i + 1), r.name(), where);
                    assertEquals("khepera", r.model(), where);
                    for (int j = 0; j < i; j++) {
                        RobotSpec q = w.robots().get(j);
                        assertTrue(Math.hypot(r.x() - q.x(), r.z() - q.z()) > apart - 1e-9, where + ": robots " + j + " and " + i + " apart");
                    }
                }
                assertTrue(w.cylinders().size() >= 10 && w.cylinders().size() <= 14, where + ": " + w.cylinders().size() + " cylinders");
                assertNotNull(w.storage(), where);
                assertNotNull(w.charger(), where);
                assertTrue(w.arena().width() >= 1.5 && w.arena().depth() >= 1.5, where);
                assertTrue(w.events().isEmpty(), where + ": no scripted faults yet");
                if (n <= WorldGenerator.TEAM_SLOTS) {
                    assertEquals(one.cylinders(), w.cylinders(), where);
                    assertEquals(one.boxes(), w.boxes(), where);
                    assertEquals(one.storage(), w.storage(), where);
                    assertEquals(one.robots().get(0), w.robots().get(0), where);
                }
            }
        }
        assertEquals(WorldGenerator.team(2, 5).generate().json(), WorldGenerator.team(2, 5).generate().json());
        assertNotEquals(WorldGenerator.team(2, 5).generate().json(), WorldGenerator.team(2, 6).generate().json());
        assertEquals("team-delivery-2-gen-5", WorldGenerator.team(2, 5).generate().spec().name());
    }

    @Test
    void aTeamHasOneToEightRobots() {
        assertEquals("a team has 1 to 8 robots, got 0",
                assertThrows(IllegalArgumentException.class, () -> WorldGenerator.team(0, 1)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> WorldGenerator.team(9, 1));
    }
}
