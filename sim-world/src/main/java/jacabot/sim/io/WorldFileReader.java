package jacabot.sim.io;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import jacabot.sim.geom.Rgb;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.EventSpec;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * Reads a JSON world file into a checked {@link WorldSpec}: types, ranges, unknown fields,
 * references between names, and the start-up geometry ({@link WorldChecks}). The first problem
 * found is reported as a {@link WorldFileException} with its JSON path. See sim-world/README.md
 * for the format.
 */
public final class WorldFileReader {
    static final Set<String> TOP = Set.of("name", "description", "arena", "basicTimeStep", "controlStep", "seed",
            "sensorNoise", "walls", "boxes", "cylinders", "storage", "charger", "robots", "events");
    static final Set<String> ARENA = Set.of("width", "depth", "wallThickness", "wallHeight", "floorColor", "wallColor");
    static final Set<String> BOX = Set.of("id", "x", "z", "size", "heading", "height", "movable", "mass", "color");
    static final Set<String> WALL = Set.of("id", "x", "z", "size", "heading", "height", "color");
    static final Set<String> CYLINDER = Set.of("id", "x", "z", "radius", "height", "mass", "color");
    static final Set<String> STORAGE = Set.of("x", "z", "radius");
    static final Set<String> CHARGER = Set.of("x", "z", "radius", "power");
    static final Set<String> ROBOT = Set.of("name", "model", "x", "z", "heading", "battery");
    static final Set<String> EVENT = Set.of("at", "when", "after", "do", "object", "robot", "x", "z", "heading", "box",
            "cylinder", "amount");
    static final Set<String> NEAR = Set.of("robot", "near", "within");

    private WorldFileReader() {
    }

    /** Reads and checks a world file. */
    public static WorldSpec read(Path file) throws WorldFileException {
        String text;
        try {
            text = Files.readString(file);
        } catch (NoSuchFileException e) {
            // said as the other commands say it, not by the exception's class and the name again
            throw new WorldFileException(file.toString(), "$", "cannot read the world file (no such file)");
        } catch (IOException e) {
            throw new WorldFileException(file.toString(), "$", "cannot read the world file (" + e.getClass().getSimpleName()
                    + (e.getMessage() == null ? "" : ": " + e.getMessage()) + ")");
        }
        String fileName = file.getFileName() == null ? file.toString() : file.getFileName().toString();
        String defaultName = fileName.endsWith(".json") ? fileName.substring(0, fileName.length() - 5) : fileName;
        return parse(text, file.toString(), defaultName);
    }

    /** Parses and checks a world file's text; {@code source} names it in messages. */
    public static WorldSpec parse(String json, String source) throws WorldFileException {
        return parse(json, source, source == null ? "world" : source);
    }

    private static WorldSpec parse(String json, String source, String defaultName) throws WorldFileException {
        JsonNode root;
        try {
            ObjectMapper mapper = new ObjectMapper();
            mapper.enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION);
            root = mapper.readTree(json);
        } catch (JsonProcessingException e) {
            String where = e.getLocation() == null ? ""
                    : " at line " + e.getLocation().getLineNr() + ", column " + e.getLocation().getColumnNr();
            throw new WorldFileException(source, "$", "not valid JSON" + where + ": " + e.getOriginalMessage());
        }
        if (root == null || root.isMissingNode()) {
            throw new WorldFileException(source, "$", "the file is empty");
        }
        try {
            return new WorldFileReader.Parser(defaultName).world(new JsonCursor(root, "$"));
        } catch (JsonCursor.Failure f) {
            throw new WorldFileException(source, f.path, f.getMessage());
        }
    }

    /** One parse: knows the arena and the robots' models for later checks. */
    private static final class Parser {
        private final String defaultName;
        private final WorldChecks checks = new WorldChecks();

        Parser(String defaultName) {
            this.defaultName = defaultName;
        }

        WorldSpec world(JsonCursor c) {
            c.object(TOP);
            String name = c.string("name", defaultName);
            if (c.has("description")) {
                c.string("description");
            }
            ArenaSpec arena = c.has("arena") ? arena(c.field("arena"))
                    : new ArenaSpec(1.0, 1.0, 0.02, 0.1, new Rgb(140, 140, 140), Rgb.WHITE);
            checks.arena(arena);
            long basic = c.integer("basicTimeStep", 8);
            if (basic <= 0 || basic > 1000) {
                throw c.field("basicTimeStep").fail("must be in 1..1000 ms, got " + basic);
            }
            long control = c.integer("controlStep", 40);
            if (control <= 0 || control % basic != 0) {
                throw c.field("controlStep").fail("must be a positive multiple of basicTimeStep (" + basic + " ms), got " + control);
            }
            long seed = c.integer("seed", 0);
            boolean noise = c.bool("sensorNoise", true);
            List<BoxSpec> walls = new ArrayList<>();
            for (JsonCursor w : c.array("walls")) {
                walls.add(checks.place(w, "wall", box(w.object(WALL), "wall" + walls.size(), false, arena)));
            }
            List<BoxSpec> boxes = new ArrayList<>();
            for (JsonCursor b : c.array("boxes")) {
                boxes.add(checks.place(b, "box", box(b.object(BOX), "box" + boxes.size(), true, arena)));
            }
            List<CylinderSpec> cylinders = new ArrayList<>();
            for (JsonCursor y : c.array("cylinders")) {
                cylinders.add(checks.place(y, cylinder(y, "cylinder" + cylinders.size())));
            }
            AreaSpec storage = c.has("storage") ? area(c.field("storage"), false) : null;
            AreaSpec charger = c.has("charger") ? area(c.field("charger"), true) : null;
            List<RobotSpec> robots = new ArrayList<>();
            for (JsonCursor r : c.array("robots")) {
                robots.add(robot(r));
            }
            List<EventSpec> events = new ArrayList<>();
            for (JsonCursor e : c.array("events")) {
                events.add(event(e, arena));
            }
            return new WorldSpec(name, arena, (int) basic, (int) control, seed, noise, walls, boxes, cylinders, storage,
                    charger, robots, events);
        }

        ArenaSpec arena(JsonCursor c) {
            c.object(ARENA);
            return new ArenaSpec(c.positive("width", 1.0), c.positive("depth", 1.0), c.positive("wallThickness", 0.02),
                    c.positive("wallHeight", 0.1), c.color("floorColor", new Rgb(140, 140, 140)), c.color("wallColor", Rgb.WHITE));
        }

        BoxSpec box(JsonCursor c, String defaultId, boolean obstacle, ArenaSpec arena) {
            String id = c.string("id", defaultId);
            double x = c.number("x"), z = c.number("z");
            double[] size = size(c);
            double heading = c.number("heading", 0);
            double height = c.positive("height", obstacle ? size[0] : arena.wallHeight());
            boolean movable = obstacle && c.bool("movable", false);
            double mass = obstacle ? c.positive("mass", 0.2) : 0;
            Rgb color = c.color("color", obstacle ? new Rgb(255, 240, 200) : arena.wallColor());
            return new BoxSpec(id, x, z, size[0], size[1], heading, height, movable, mass, color);
        }

        /** "size": a number (a square) or [sizeX, sizeZ]. */
        double[] size(JsonCursor c) {
            JsonCursor s = c.field("size");
            double sx, sz;
            if (s.json.isArray()) {
                if (s.json.size() != 2) {
                    throw s.fail("expected [sizeX, sizeZ], got " + s.json.size() + " numbers");
                }
                sx = new JsonCursor(s.json.get(0), s.path + "[0]").asNumber();
                sz = new JsonCursor(s.json.get(1), s.path + "[1]").asNumber();
            } else {
                sx = s.asNumber();
                sz = sx;
            }
            if (sx <= 0 || sz <= 0) {
                throw s.fail("sizes must be > 0");
            }
            return new double[] {sx, sz};
        }

        CylinderSpec cylinder(JsonCursor c, String defaultId) {
            c.object(CYLINDER);
            return new CylinderSpec(c.string("id", defaultId), c.number("x"), c.number("z"), c.positive("radius", 0.0125),
                    c.positive("height", 0.04), c.positive("mass", 0.02), c.color("color", Rgb.RED));
        }

        AreaSpec area(JsonCursor c, boolean charger) {
            c.object(charger ? CHARGER : STORAGE);
            AreaSpec a = new AreaSpec(c.number("x"), c.number("z"), c.positive("radius", 0.08),
                    charger ? c.positive("power", 20) : 0);
            checks.areaInside(c, a);
            return a;
        }

        RobotSpec robot(JsonCursor c) {
            c.object(ROBOT);
            String name = c.string("name");
            String modelName = c.string("model");
            RobotModel model = RobotModel.byName(modelName).orElseThrow(() -> c.field("model")
                    .fail("unknown robot model '" + modelName + "' (known: " + String.join(", ", RobotModel.names()) + ")"));
            double battery = Double.NaN;
            if (c.has("battery")) {
                JsonCursor b = c.field("battery");
                if (model.battery() == null) {
                    throw b.fail("model '" + modelName + "' has no battery");
                }
                battery = b.asNumber();
                if (battery < 0 || battery > model.battery().maxEnergy()) {
                    throw b.fail("must be in 0.." + model.battery().maxEnergy() + " J, got " + battery);
                }
            }
            RobotSpec r = new RobotSpec(name, modelName, c.number("x", 0), c.number("z", 0), c.number("heading", 0), battery);
            checks.place(c, r, model);
            return r;
        }

        EventSpec event(JsonCursor c, ArenaSpec arena) {
            c.object(EVENT);
            EventSpec.Trigger trigger;
            if (c.has("at") == c.has("when")) {
                throw c.fail("an event needs exactly one of \"at\" (seconds) or \"when\" (a proximity condition)");
            }
            if (c.has("at")) {
                trigger = new EventSpec.At(c.nonNegative("at", 0));
            } else {
                JsonCursor w = c.field("when").object(NEAR);
                String robot = checks.robotName(w.field("robot"));
                String object = checks.objectName(w.field("near"));
                trigger = new EventSpec.Near(robot, object, w.positive("within", 0.1));
            }
            double after = c.nonNegative("after", 0);
            String kind = c.string("do");
            EventSpec.Action action;
            switch (kind) {
                case "move":
                    action = new EventSpec.Move(checks.objectName(c.field("object")), c.number("x"), c.number("z"),
                            c.number("heading", Double.NaN));
                    checks.pointInside(c, c.number("x"), c.number("z"));
                    break;
                case "add":
                    if (c.has("box") == c.has("cylinder")) {
                        throw c.fail("\"add\" needs exactly one of \"box\" or \"cylinder\"");
                    }
                    if (c.has("box")) {
                        JsonCursor b = c.field("box");
                        BoxSpec box = box(b.object(BOX), "box-added" + checks.added(), true, arena);
                        checks.inside(b, box);
                        action = new EventSpec.AddBox(checks.added(b, box.id(), box));
                    } else {
                        JsonCursor y = c.field("cylinder");
                        CylinderSpec cyl = cylinder(y, "cylinder-added" + checks.added());
                        checks.inside(y, cyl);
                        action = new EventSpec.AddCylinder(checks.added(y, cyl.id(), cyl));
                    }
                    break;
                case "remove":
                    action = new EventSpec.Remove(checks.objectName(c.field("object")));
                    break;
                case "knock":
                    action = new EventSpec.Knock(checks.gripperRobot(c.field("robot")));
                    break;
                case "drain":
                    action = new EventSpec.Drain(checks.batteryRobot(c.field("robot")), c.positive("amount", 100));
                    break;
                default:
                    throw c.field("do").fail("unknown event action '" + kind + "' (known: move, add, remove, knock, drain)");
            }
            return new EventSpec(trigger, after, action);
        }
    }
}
