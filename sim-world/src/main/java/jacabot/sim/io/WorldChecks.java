package jacabot.sim.io;

import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.Footprint;
import jacabot.sim.world.RobotSpec;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** The checks that span several parts of a world file: names, references and start-up geometry. Internal. */
final class WorldChecks {
    private record Placed(String description, Footprint footprint) {
    }

    private ArenaSpec arena;
    private final Map<String, String> names = new LinkedHashMap<>(); // id -> description
    private final Map<String, RobotModel> robots = new LinkedHashMap<>();
    private final List<Placed> placed = new ArrayList<>();
    private int added;

    void arena(ArenaSpec a) {
        this.arena = a;
        for (String w : List.of("wall-north", "wall-south", "wall-east", "wall-west")) {
            names.put(w, "arena wall '" + w + "'");
        }
    }

    private void name(JsonCursor c, String field, String id, String description) {
        if (names.containsKey(id)) {
            JsonCursor at = c.has(field) ? c.field(field) : c;
            throw at.fail("the name '" + id + "' is already used by " + names.get(id));
        }
        names.put(id, description);
    }

    private void fits(JsonCursor c, String description, Footprint f) {
        if (!f.inside(arena.halfWidth(), arena.halfDepth())) {
            throw c.fail(description + " lies outside the arena (x in [" + -arena.halfWidth() + ", " + arena.halfWidth()
                    + "], z in [" + -arena.halfDepth() + ", " + arena.halfDepth() + "])");
        }
        for (Placed p : placed) {
            if (p.footprint.overlaps(f)) {
                throw c.fail(description + " overlaps " + p.description + " at start");
            }
        }
        placed.add(new Placed(description, f));
    }

    BoxSpec place(JsonCursor c, String kind, BoxSpec b) {
        String d = kind + " '" + b.id() + "'";
        name(c, "id", b.id(), d);
        fits(c, d, Footprint.rectangle(b.x(), b.z(), b.sizeX(), b.sizeZ(), b.heading()));
        return b;
    }

    CylinderSpec place(JsonCursor c, CylinderSpec y) {
        String d = "cylinder '" + y.id() + "'";
        name(c, "id", y.id(), d);
        fits(c, d, Footprint.circle(y.x(), y.z(), y.radius()));
        return y;
    }

    void place(JsonCursor c, RobotSpec r, RobotModel model) {
        String d = "robot '" + r.name() + "'";
        name(c, "name", r.name(), d);
        robots.put(r.name(), model);
        fits(c, d, Footprint.circle(r.x(), r.z(), model.radius()));
    }

    void areaInside(JsonCursor c, AreaSpec a) {
        pointInside(c, a.x(), a.z());
    }

    void pointInside(JsonCursor c, double x, double z) {
        if (Math.abs(x) > arena.halfWidth() || Math.abs(z) > arena.halfDepth()) {
            throw c.fail("the point (" + x + ", " + z + ") lies outside the arena");
        }
    }

    void inside(JsonCursor c, BoxSpec b) {
        if (!Footprint.rectangle(b.x(), b.z(), b.sizeX(), b.sizeZ(), b.heading()).inside(arena.halfWidth(), arena.halfDepth())) {
            throw c.fail("box '" + b.id() + "' lies outside the arena");
        }
    }

    void inside(JsonCursor c, CylinderSpec y) {
        if (!Footprint.circle(y.x(), y.z(), y.radius()).inside(arena.halfWidth(), arena.halfDepth())) {
            throw c.fail("cylinder '" + y.id() + "' lies outside the arena");
        }
    }

    int added() {
        return added;
    }

    <T> T added(JsonCursor c, String id, T spec) {
        name(c, "id", id, "an object added by an earlier event");
        added++;
        return spec;
    }

    String robotName(JsonCursor c) {
        String name = text(c);
        if (!robots.containsKey(name)) {
            throw c.fail("no robot named '" + name + "' (robots: " + String.join(", ", robots.keySet()) + ")");
        }
        return name;
    }

    String objectName(JsonCursor c) {
        String name = text(c);
        if (!names.containsKey(name) || name.startsWith("wall-")) {
            throw c.fail("no box, cylinder or robot named '" + name + "'");
        }
        return name;
    }

    String gripperRobot(JsonCursor c) {
        String name = robotName(c);
        if (robots.get(name).gripper() == null) {
            throw c.fail("robot '" + name + "' (" + robots.get(name).name() + ") has no gripper");
        }
        return name;
    }

    String batteryRobot(JsonCursor c) {
        String name = robotName(c);
        if (robots.get(name).battery() == null) {
            throw c.fail("robot '" + name + "' (" + robots.get(name).name() + ") has no battery");
        }
        return name;
    }

    private static String text(JsonCursor c) {
        if (!c.json.isTextual()) {
            throw c.fail("expected a name, got " + JsonCursor.describe(c.json));
        }
        return c.json.asText();
    }
}
