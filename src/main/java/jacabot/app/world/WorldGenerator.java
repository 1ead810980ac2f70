package jacabot.app.world;

import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.Footprint;
import jacabot.sim.world.WorldSpec;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Makes a random world file for an experiment, or for a team's ({@link #team}), the same text for
 * the same seed: an arena of 1 to {@link #maxSide} metres a side, sparse to dense cubic obstacles,
 * the storage point and the charger in a corner or along a wall, red cylinders, and scripted faults
 * at random times (obstacles moved, a cylinder moved while the robot grips it, a carried cylinder
 * knocked out, the battery drained). Robot model and battery are those of the experiment's default
 * world.
 *
 * <p>A team's world (thesis Chapter 6: {@code team-delivery}, several Kheperas bringing about a dozen
 * cylinders to one storage point and recharging at one charger) is made by the same steps with
 * several robots, placed apart, more cylinders, an arena of at least 1.5 m and no scripted faults
 * yet. Its robots' places are drawn for {@link #TEAM_SLOTS} robots whatever the team's size (more
 * for a larger team), so that one seed gives teams of 1 to 4 robots the same arena, obstacles and
 * cylinders: their runs compare.
 *
 * <p>Reachability by construction: every obstacle keeps more than a robot's diameter
 * ({@link #gap}) from every other obstacle, from the walls and from the areas, so the floor the
 * robot's centre can reach is one connected region holding every cylinder, the storage point and
 * the charger. Nothing starts on the robot or on another object; moved obstacles go to places that
 * were free at start (the robot may stand there by then: physics pushes, as in Webots). The text is
 * checked with the world loader before it is returned.
 */
public final class WorldGenerator {
    /** The result: the JSON text and the loaded world. */
    public record Generated(String json, WorldSpec spec) {
    }

    /** The obstacles' share of the floor: sparse to dense. */
    static final double MIN_DENSITY = 0.01, MAX_DENSITY = 0.06;
    /** The narrowest passage between two obstacles or an obstacle and a wall, metres. */
    static final double MIN_GAP = 0.12;

    /** Robots' places drawn for a team world whatever its size, so that teams of 1 to this many share a layout. */
    public static final int TEAM_SLOTS = 4;
    /** The largest team a world is generated for. */
    public static final int MAX_TEAM = 8;
    /** The team experiment's name in files and on the command line. */
    public static final String TEAM_DELIVERY = "team-delivery";

    /** Mixed into a team world's seed after the experiments' 1 to 4: a constant, so that no new experiment changes team worlds. */
    private static final long TEAM_SALT = 5;

    /** What varies between the experiments' worlds; {@code experiment} is null for a team's. */
    private record Recipe(Experiment experiment, String id, String command, String purpose, long salt, int robots,
                          boolean storage, boolean charger, double minSide) {
    }

    private final Recipe recipe;
    private final Experiment experiment;
    private final long seed;
    private double maxSide = 3.0;

    private SplittableRandom random;
    private RobotModel model;
    private double halfW, halfD, gap;
    private final List<Footprint> placed = new ArrayList<>();
    private final List<double[]> free = new ArrayList<>(); // circles (x, z, r) kept clear of obstacles

    public WorldGenerator(Experiment experiment, long seed) {
        this(new Recipe(experiment, experiment.id(), experiment.id(), "experiment " + experiment.number(), experiment.ordinal() + 1L, 1,
                experiment.needsStorage(), experiment.needsCharger(), 1.0), seed);
    }

    private WorldGenerator(Recipe recipe, long seed) {
        this.recipe = recipe;
        this.experiment = recipe.experiment();
        this.seed = seed;
    }

    /**
     * {@return a generator of team-delivery worlds for {@code robots} Kheperas, named khepera1 to
     * kheperaN} @throws IllegalArgumentException for fewer than 1 or more than {@link #MAX_TEAM} robots
     */
    public static WorldGenerator team(int robots, long seed) {
        if (robots < 1 || robots > MAX_TEAM) {
            throw new IllegalArgumentException("a team has 1 to " + MAX_TEAM + " robots, got " + robots);
        }
        return new WorldGenerator(new Recipe(null, TEAM_DELIVERY + "-" + robots, TEAM_DELIVERY + " --robots " + robots,
                "the team-delivery experiment (" + robots + " Khepera" + (robots == 1 ? "" : "s") + ")",
                TEAM_SALT, robots, true, true, 1.5), seed);
    }

    /** {@return the name of robot {@code i} (0-based) of a team} */
    public static String teamRobot(int i) {
        return "khepera" + (i + 1);
    }

    /** The largest arena side, metres (at least 1; default 3). */
    public WorldGenerator maxSide(double metres) {
        if (!(metres >= 1)) {
            throw new IllegalArgumentException("the largest arena side must be at least 1 m, got " + metres);
        }
        this.maxSide = metres;
        return this;
    }

    /** {@return the world text, checked by the loader} */
    public Generated generate() {
        // one draw mixes the seed: SplittableRandom(seed * gamma) made seed k's second draw seed k+1's first
        random = new SplittableRandom(new SplittableRandom(seed ^ recipe.salt() * 0xD1B54A32D192ED03L).nextLong());
        placed.clear();
        free.clear();
        model = experiment == Experiment.OBSTACLE_AVOIDANCE ? RobotModel.MYBOT : RobotModel.KHEPERA;
        // passages at least twice the Khepera's width: a gap the robot's own sensors read as a wall on
        // both sides is a dead end, not a passage
        gap = Math.max(2 * model.radius() + 0.03, MIN_GAP);
        double width = round2(uniform(recipe.minSide(), maxSide));
        double depth = round2(uniform(recipe.minSide(), maxSide));
        halfW = width / 2;
        halfD = depth / 2;
        String name = recipe.id() + "-gen-" + seed;
        Json j = new Json();
        j.open().field("name", name)
                .field("description", "Generated by `jacabot world generate " + recipe.command() + " --seed " + seed
                        + "`: a random world for " + recipe.purpose() + ".")
                .raw("arena", "{ \"width\": " + num(width) + ", \"depth\": " + num(depth)
                        + ", \"wallThickness\": 0.02, \"wallHeight\": 0.1 }")
                .raw("basicTimeStep", "8").raw("controlStep", "40").raw("seed", Long.toString(seed));

        boolean needsStorage = recipe.storage();
        boolean needsCharger = recipe.charger();
        double areaRadius = 0.06;
        double[] storage = null, charger = null;
        if (needsStorage) {
            storage = landmark(areaRadius, null);
            free.add(new double[] {storage[0], storage[1], areaRadius + gap});
        }
        if (needsCharger) {
            charger = landmark(areaRadius, storage);
            free.add(new double[] {charger[0], charger[1], areaRadius + gap});
        }
        // the robots first, with room around each
        List<String> robots = new ArrayList<>();
        int slots = experiment != null ? 1 : Math.max(recipe.robots(), TEAM_SLOTS);
        for (int i = 0; i < slots; i++) {
            double[] robot = spot(model.radius(), model.radius() + 0.02, 0.05);
            if (robot == null) {
                throw new IllegalStateException("no room for robot " + (i + 1) + " (a bug: arenas hold " + MAX_TEAM + ")");
            }
            double heading = Math.round(random.nextDouble(0, 360));
            placed.add(Footprint.circle(robot[0], robot[1], model.radius()));
            free.add(new double[] {robot[0], robot[1], model.radius() + gap});
            String battery = experiment != null && needsCharger ? ", \"battery\": 560"
                    : experiment == null ? ", \"battery\": " + num(10 * Math.round(random.nextDouble(45, 70))) : "";
            if (i < recipe.robots()) {
                robots.add("{ \"name\": \"" + (experiment != null ? experiment.robot() : teamRobot(i)) + "\", \"model\": \""
                        + model.name() + "\", \"x\": " + num(robot[0]) + ", \"z\": " + num(robot[1]) + ", \"heading\": "
                        + num(heading) + battery + " }");
            }
        }

        // cylinders before the boxes, so that boxes keep clear of them
        List<String> cylinders = new ArrayList<>();
        List<String> cylinderIds = new ArrayList<>();
        int nCylinders = experiment == null ? 10 + random.nextInt(5) : switch (experiment) {
            case OBSTACLE_AVOIDANCE -> 0;
            case OBJECT_PICKING -> 1 + random.nextInt(3);
            default -> 2 + random.nextInt(3);
        };
        for (int i = 0; i < nCylinders; i++) {
            double r = 0.0125;
            double[] p = spot(r, gap, 0.0);
            if (p == null) {
                break;
            }
            placed.add(Footprint.circle(p[0], p[1], r));
            free.add(new double[] {p[0], p[1], r + gap});
            String id = "red" + (i + 1);
            cylinderIds.add(id);
            cylinders.add("{ \"id\": \"" + id + "\", \"x\": " + num(p[0]) + ", \"z\": " + num(p[1]) + ", \"color\": \"red\" }");
        }

        // obstacles: density = the share of the floor they cover, sparse (1 %) to dense (6 %, three
        // times the default worlds' 2 %; 12 % made mazes of 80 boxes that no controller crossed)
        double density = uniform(MIN_DENSITY, MAX_DENSITY);
        double target = density * width * depth;
        double covered = 0;
        List<String> boxes = new ArrayList<>();
        List<double[]> boxSpots = new ArrayList<>();
        for (int attempt = 0; attempt < 400 && covered < target; attempt++) {
            double sx = round3(uniform(0.04, 0.10));
            double sz = random.nextInt(3) == 0 ? round3(uniform(0.04, 0.12)) : sx;
            double h = random.nextInt(2) == 0 ? 0 : Math.round(random.nextDouble(0, 90));
            double x = round3(uniform(-halfW + gap + 0.06, halfW - gap - 0.06));
            double z = round3(uniform(-halfD + gap + 0.06, halfD - gap - 0.06));
            Footprint f = Footprint.rectangle(x, z, sx, sz, h);
            Footprint grown = Footprint.rectangle(x, z, sx + 2 * gap, sz + 2 * gap, h);
            if (!grown.inside(halfW, halfD) || !clear(grown, f)) {
                continue;
            }
            placed.add(f);
            boxSpots.add(new double[] {x, z, sx, sz, h});
            boolean movable = random.nextInt(5) == 0;
            String id = "box" + (boxes.size() + 1);
            boxes.add("{ \"id\": \"" + id + "\", \"x\": " + num(x) + ", \"z\": " + num(z) + ", \"size\": "
                    + (sx == sz ? num(sx) : "[" + num(sx) + ", " + num(sz) + "]")
                    + (h != 0 ? ", \"heading\": " + num(h) : "") + (movable ? ", \"movable\": true, \"mass\": 0.3" : "") + " }");
            covered += sx * sz;
        }

        List<String> events = experiment == null ? List.of() : faults(boxSpots, cylinderIds);

        j.array("boxes", boxes);
        if (!cylinders.isEmpty()) {
            j.array("cylinders", cylinders);
        }
        if (storage != null) {
            j.raw("storage", "{ \"x\": " + num(storage[0]) + ", \"z\": " + num(storage[1]) + ", \"radius\": " + num(areaRadius) + " }");
        }
        if (charger != null) {
            j.raw("charger", "{ \"x\": " + num(charger[0]) + ", \"z\": " + num(charger[1]) + ", \"radius\": "
                    + num(areaRadius) + ", \"power\": 20 }");
        }
        j.array("robots", robots);
        if (!events.isEmpty()) {
            j.array("events", events);
        }
        String json = j.close();
        try {
            return new Generated(json, WorldFileReader.parse(json, name + ".json"));
        } catch (WorldFileException e) {
            throw new IllegalStateException("the generator made an invalid world (a bug): " + e.getMessage(), e);
        }
    }

    /** Scripted faults at random times: 0 to 3 of those that make sense for the experiment. */
    private List<String> faults(List<double[]> boxes, List<String> cylinders) {
        List<String> kinds = new ArrayList<>();
        if (!boxes.isEmpty()) {
            kinds.add("move-box");
        }
        if (!cylinders.isEmpty()) {
            kinds.add("move-cylinder-in-grip");
            kinds.add("knock");
        }
        if (experiment.needsCharger()) {
            kinds.add("drain");
        }
        List<String> events = new ArrayList<>();
        int n = kinds.isEmpty() ? 0 : random.nextInt(4);
        for (int i = 0; i < n; i++) {
            String kind = kinds.get(random.nextInt(kinds.size()));
            double at = Math.round(random.nextDouble(20, 480));
            String robot = experiment.robot();
            switch (kind) {
                case "move-box" -> {
                    int b = random.nextInt(boxes.size());
                    double[] box = boxes.get(b);
                    double[] to = spotForBox(box);
                    if (to != null) {
                        events.add("{ \"at\": " + num(at) + ", \"do\": \"move\", \"object\": \"box" + (b + 1) + "\", \"x\": "
                                + num(to[0]) + ", \"z\": " + num(to[1]) + " }");
                    }
                }
                case "move-cylinder-in-grip" -> {
                    // when the robot is about to take hold of it (centres within reach), the cylinder jumps away
                    String c = cylinders.get(random.nextInt(cylinders.size()));
                    double[] to = spot(0.0125, gap, 0.0);
                    if (to != null) {
                        placed.add(Footprint.circle(to[0], to[1], 0.0125));
                        events.add("{ \"when\": { \"robot\": \"" + robot + "\", \"near\": \"" + c + "\", \"within\": "
                                + num(model.radius() + 0.03) + " }, \"after\": " + num(round2(uniform(0.2, 2.0)))
                                + ", \"do\": \"move\", \"object\": \"" + c + "\", \"x\": " + num(to[0]) + ", \"z\": " + num(to[1]) + " }");
                    }
                }
                case "knock" -> {
                    // some seconds after the robot reached a cylinder: knocked out if it carries it then
                    String c = cylinders.get(random.nextInt(cylinders.size()));
                    events.add("{ \"when\": { \"robot\": \"" + robot + "\", \"near\": \"" + c + "\", \"within\": "
                            + num(model.radius() + 0.03) + " }, \"after\": " + num(Math.round(random.nextDouble(4, 20)))
                            + ", \"do\": \"knock\", \"robot\": \"" + robot + "\" }");
                }
                default -> events.add("{ \"at\": " + num(at) + ", \"do\": \"drain\", \"robot\": \"" + robot + "\", \"amount\": "
                        + num(Math.round(random.nextDouble(100, 300))) + " }");
            }
        }
        return events;
    }

    /** A corner or a place along a wall for an area of radius r, far from {@code other}. */
    private double[] landmark(double r, double[] other) {
        double inset = r + 0.02;
        for (int attempt = 0; attempt < 200; attempt++) {
            double x, z;
            int wall = random.nextInt(4);
            boolean corner = random.nextBoolean();
            double along = corner ? (random.nextBoolean() ? 1 : -1) : uniform(-0.8, 0.8);
            switch (wall) {
                case 0 -> { x = halfW - inset; z = along * (halfD - inset); }
                case 1 -> { x = -(halfW - inset); z = along * (halfD - inset); }
                case 2 -> { z = halfD - inset; x = along * (halfW - inset); }
                default -> { z = -(halfD - inset); x = along * (halfW - inset); }
            }
            x = round3(x);
            z = round3(z);
            if (other == null || Math.hypot(x - other[0], z - other[1]) >= 0.5) {
                return new double[] {x, z};
            }
        }
        throw new IllegalStateException("no room for a landmark (a bug: arenas are at least 1 m a side)");
    }

    /** A random free centre for a circle of radius r keeping {@code clearance} from the walls and every object. */
    private double[] spot(double r, double clearance, double extra) {
        for (int attempt = 0; attempt < 500; attempt++) {
            double m = r + clearance + extra;
            double x = round3(uniform(-halfW + m, halfW - m));
            double z = round3(uniform(-halfD + m, halfD - m));
            Footprint grown = Footprint.circle(x, z, r + clearance);
            if (clear(grown, Footprint.circle(x, z, r))) {
                return new double[] {x, z};
            }
        }
        return null;
    }

    /** A free place for a box of {@code box}'s size (for a "move" fault). */
    private double[] spotForBox(double[] box) {
        for (int attempt = 0; attempt < 200; attempt++) {
            double x = round3(uniform(-halfW + gap + 0.06, halfW - gap - 0.06));
            double z = round3(uniform(-halfD + gap + 0.06, halfD - gap - 0.06));
            Footprint grown = Footprint.rectangle(x, z, box[2] + 2 * gap, box[3] + 2 * gap, box[4]);
            Footprint body = Footprint.rectangle(x, z, box[2], box[3], box[4]);
            if (grown.inside(halfW, halfD) && clear(grown, body)) {
                placed.add(body);
                return new double[] {x, z};
            }
        }
        return null;
    }

    /** Whether {@code grown} (the new object with its clearance) overlaps no placed object and {@code body} no kept-free circle. */
    private boolean clear(Footprint grown, Footprint body) {
        for (Footprint p : placed) {
            if (p.overlaps(grown)) {
                return false;
            }
        }
        for (double[] c : free) {
            if (body.overlaps(Footprint.circle(c[0], c[1], c[2]))) {
                return false;
            }
        }
        return true;
    }

    private double uniform(double lo, double hi) {
        return lo >= hi ? lo : random.nextDouble(lo, hi);
    }

    private static double round2(double v) {
        return Math.round(v * 100) / 100.0;
    }

    private static double round3(double v) {
        return Math.round(v * 1000) / 1000.0;
    }

    private static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e9) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "");
    }

    /** A small JSON writer: one member per line, arrays one element per line. */
    private static final class Json {
        private final StringBuilder b = new StringBuilder();
        private boolean first = true;

        Json open() {
            b.append("{\n");
            return this;
        }

        private void key(String k) {
            b.append(first ? "" : ",\n").append("  \"").append(k).append("\": ");
            first = false;
        }

        Json field(String k, String text) {
            key(k);
            b.append('"').append(text.replace("\\", "\\\\").replace("\"", "\\\"")).append('"');
            return this;
        }

        Json raw(String k, String json) {
            key(k);
            b.append(json);
            return this;
        }

        Json array(String k, List<String> items) {
            key(k);
            if (items.isEmpty()) {
                b.append("[]");
                return this;
            }
            b.append("[\n");
            for (int i = 0; i < items.size(); i++) {
                b.append("    ").append(items.get(i)).append(i + 1 < items.size() ? ",\n" : "\n");
            }
            b.append("  ]");
            return this;
        }

        String close() {
            return b.append("\n}\n").toString();
        }
    }
}
