package jacabot.app.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.world.WorldGenerator.Profile;
import jacabot.robot.Experiment;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.EventSpec;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The wide profile's invariants, and the classic profile's worlds kept as they were. */
class WideWorldsTest {
    /** The first 16 hex digits of SHA-256 of worlds made before the profiles existed (`jacabot world generate E --seed S`). */
    private static final Map<String, String> CLASSIC = Map.ofEntries(
            Map.entry("obstacle-avoidance 1", "074a721f4316712d"), Map.entry("obstacle-avoidance 51", "c826ab11433e161c"),
            Map.entry("object-picking 7", "f61c6745eabc9758"), Map.entry("navigation 1", "538137638c4c5890"),
            Map.entry("navigation 51", "b4a89ccc0e0ddc01"), Map.entry("suspend-resume 7", "af5dcaf16ac3f35f"),
            Map.entry("tidy-up 1", "ddee75ad588b945d"), Map.entry("tidy-up 51", "595a26b3c45de696"));

    @Test
    void classicWorldsAreTheSameTextAsBeforeTheProfiles() throws Exception {
        for (var e : CLASSIC.entrySet()) {
            String[] key = e.getKey().split(" ");
            Experiment x = Experiment.parse(key[0]).orElseThrow();
            long seed = Long.parseLong(key[1]);
            String json = new WorldGenerator(x, seed).profile(Profile.CLASSIC).generate().json();
            assertEquals(json, new WorldGenerator(x, seed).generate().json(), "classic is the default");
            byte[] sha = MessageDigest.getInstance("SHA-256").digest(json.getBytes(StandardCharsets.UTF_8));
            assertEquals(e.getValue(), HexFormat.of().formatHex(sha).substring(0, 16), e.getKey());
        }
        assertEquals("a86377aca3fb8253", HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256")
                .digest(WorldGenerator.team(3, 4).generate().json().getBytes(StandardCharsets.UTF_8))).substring(0, 16));
    }

    /** Every wide world: sizes in range, and everything the task needs where the robot's centre can get. */
    @Test
    void wideWorldsAskOnlyForWhatTheRobotCanReach() {
        int walls = 0, corridors = 0, closed = 0, sliding = 0, open = 0, inside = 0;
        double narrowest = 1, smallest = 9, largest = 0;
        for (Experiment e : Experiment.values()) {
            for (long seed = 1; seed <= 12; seed++) {
                WorldSpec w = new WorldGenerator(e, seed).profile(Profile.WIDE).generate().spec();
                String where = e.id() + " wide seed " + seed;
                assertEquals(e.id() + "-wide-" + seed, w.name());
                for (double side : new double[] {w.arena().width(), w.arena().depth()}) {
                    assertTrue(side >= 0.7 && side <= 4, where + ": side " + side);
                    smallest = Math.min(smallest, side);
                    largest = Math.max(largest, side);
                }
                RobotSpec r = w.robots().get(0);
                RobotModel model = RobotModel.byName(r.model()).orElseThrow();
                Reachability reach = Reachability.of(w, model.radius(), r.x(), r.z());
                for (CylinderSpec c : w.cylinders()) {
                    assertTrue(reach.canReach(c.x(), c.z(), model.radius() + 0.03), where + ": " + c.id() + " out of reach");
                }
                for (AreaSpec a : new AreaSpec[] {w.storage(), w.charger()}) {
                    if (a != null) {
                        assertTrue(reach.canReach(a.x(), a.z(), a.radius() / 2), where + ": area out of reach " + a);
                        double toWall = Math.min(w.arena().halfWidth() - Math.abs(a.x()), w.arena().halfDepth() - Math.abs(a.z()));
                        inside += toWall > a.radius() + 0.05 ? 1 : 0;
                    }
                }
                switch (e) {
                    case OBSTACLE_AVOIDANCE -> assertTrue(w.cylinders().isEmpty(), where);
                    case OBJECT_PICKING -> assertTrue(w.cylinders().size() >= 1, where);
                    default -> assertTrue(w.cylinders().size() >= 2, where);
                }
                if (w.walls().isEmpty()) {
                    open++;
                } else {
                    walls++;
                    double passage = passage(w.walls(), w);
                    narrowest = Math.min(narrowest, passage);
                    corridors += w.walls().get(0).sizeX() > 0.1 && w.walls().get(0).sizeZ() > 0.1 ? 1 : 0;
                    if (passage < 2 * model.radius()) {
                        closed++;
                        assertTrue(reach.reachableShare() < 0.97, where + ": a room behind a " + passage + " m passage is closed");
                    }
                }
                sliding += (int) w.boxes().stream().filter(b -> w.events().stream().filter(ev -> ev.action()
                        instanceof EventSpec.Move m && m.object().equals(b.id())).count() > 20).count();
            }
        }
        assertTrue(smallest < 0.9 && largest > 3.5, "arenas " + smallest + ".." + largest + " m");
        assertTrue(open > 5 && walls > 25 && corridors > 5 && closed >= 1, open + " open, " + walls + " with an inner wall ("
                + corridors + " corridors, " + closed + " closed rooms)");
        assertTrue(narrowest <= 0.13, "narrowest passage " + narrowest);
        assertTrue(sliding > 10 && inside > 5, sliding + " sliding boxes, " + inside + " areas away from the walls");
    }

    @Test
    void wideWorldsAreReproducibleAndNamedForTheProfile() {
        String a = new WorldGenerator(Experiment.NAVIGATION, 9).profile(Profile.WIDE).generate().json();
        assertEquals(a, new WorldGenerator(Experiment.NAVIGATION, 9).profile(Profile.WIDE).generate().json());
        assertNotEquals(a, new WorldGenerator(Experiment.NAVIGATION, 10).profile(Profile.WIDE).generate().json());
        assertTrue(a.contains("--profile wide"), a);
        WorldSpec small = new WorldGenerator(Experiment.NAVIGATION, 9).profile(Profile.WIDE).maxSide(1.2).generate().spec();
        assertTrue(small.arena().width() <= 1.2 && small.arena().depth() <= 1.2);
        assertEquals(Profile.WIDE, Profile.parse("wide"));
        assertEquals("unknown world profile 'huge' (expected classic or wide)",
                assertThrows(IllegalArgumentException.class, () -> Profile.parse("huge")).getMessage());
    }

    @Test
    void aDoorwayNarrowerThanTheRobotClosesTheRoomAndAWiderOneDoesNot() {
        for (double door : new double[] {0.08, 0.12}) {
            // a wall at x = 0 from wall to wall but for a doorway at z in [-door/2, door/2]
            double half = (2 - door) / 4;
            List<Reachability.Block> wall = List.of(new Reachability.Block(0, -1 + half, 0.02, 2 * half, 0),
                    new Reachability.Block(0, 1 - half, 0.02, 2 * half, 0));
            Reachability reach = Reachability.of(1, 1, wall, RobotModel.MYBOT.radius(), -0.5, 0.5);
            boolean passes = door > 2 * (RobotModel.MYBOT.radius() + Reachability.MARGIN);
            assertEquals(passes, reach.canReach(0.5, 0.5, 0.01), "door " + door);
            assertTrue(reach.canReach(-0.5, -0.5, 0.01));
            if (passes) {
                // around the wall's end through the doorway: longer than the straight line, not longer than the two legs
                double d = reach.distanceTo(0.5, 0.5, 0.01);
                assertTrue(d > 2 * Math.hypot(0.44, 0.5) && d < 1.7, "path " + d);
                assertEquals(400, reach.reachableCells(0.1), 5, "cells reachable");
            } else {
                assertEquals(200, reach.reachableCells(0.1), 5, "cells of one room");
                assertFalse(reach.canReach(0.05, 0, 0.005));
            }
        }
    }

    /** The widest gap between consecutive inner wall segments, or between a segment and the arena's wall. */
    private static double passage(List<BoxSpec> walls, WorldSpec w) {
        BoxSpec a = walls.get(0);
        boolean acrossX = a.sizeZ() > a.sizeX() || walls.size() == 2 && Math.abs(walls.get(1).x() - a.x()) < 1e-6;
        if (walls.size() == 1) {
            double span = acrossX ? w.arena().halfDepth() : w.arena().halfWidth();
            double len = acrossX ? a.sizeZ() : a.sizeX();
            return 2 * span - len;
        }
        BoxSpec b = walls.get(1);
        return acrossX ? (b.z() - b.sizeZ() / 2) - (a.z() + a.sizeZ() / 2) : (b.x() - b.sizeX() / 2) - (a.x() + a.sizeX() / 2);
    }
}
