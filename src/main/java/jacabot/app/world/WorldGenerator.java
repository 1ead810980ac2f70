package jacabot.app.world;

import static jacabot.app.world.Floor.num;
import static jacabot.app.world.Floor.round2;
import static jacabot.app.world.Floor.round3;

import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.CylinderSpec;
import jacabot.sim.world.RobotSpec;
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
 * (the passage {@code gap}) from every other obstacle, from the walls and from the areas, so the floor the
 * robot's centre can reach is one connected region holding every cylinder, the storage point and
 * the charger. Nothing starts on the robot or on another object; moved obstacles go to places that
 * were free at start (the robot may stand there by then: physics pushes, as in Webots). The text is
 * checked with the world loader before it is returned.
 *
 * <p>Two profiles ({@link Profile}). {@code classic} is the range the agents were first measured on
 * (above; the same text for the same seed as before the profiles existed). {@code wide} is what users'
 * arenas look like: 0.7 to 4 m a side; in seven worlds of ten an inner wall across the arena, thin with a
 * single doorway or thick with a corridor through it, 12 to 40 cm wide, and in a tenth of those
 * narrower than the robot (a room it cannot enter); the storage point and the charger anywhere on the
 * floor; up to two boxes that slide back and forth during the run. There, reachability is not by
 * construction but checked ({@link Reachability}): cylinders, the storage area and the charger are put
 * only where the robot's centre can get from its start, so nothing behind a too-narrow doorway is
 * ever asked of it; a draw that cannot be completed is drawn again from the same random stream.
 */
public final class WorldGenerator {
    /** Which range of worlds to draw from. */
    public enum Profile {
        /** Arenas of 1 to 3 m, open, areas at the walls: the range the agents were first measured on. */
        CLASSIC,
        /** Arenas of 0.7 to 4 m, inner walls with a doorway or a corridor, areas anywhere, sliding boxes. */
        WIDE;

        /** {@return the profile's name on the command line} */
        public String id() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** {@return the profile of that name} @throws IllegalArgumentException for another name */
        public static Profile parse(String name) {
            for (Profile p : values()) {
                if (p.id().equals(name)) {
                    return p;
                }
            }
            throw new IllegalArgumentException("unknown world profile '" + name + "' (expected classic or wide)");
        }

        /** {@return the largest arena side when none is given, metres} */
        public double defaultMaxSide() {
            return this == WIDE ? 4.0 : 3.0;
        }
    }

    /** The result: the JSON text and the loaded world. */
    public record Generated(String json, WorldSpec spec) {
    }

    /** The obstacles' share of the floor: sparse to dense. */
    static final double MIN_DENSITY = 0.01, MAX_DENSITY = 0.06;
    /** The narrowest passage between two obstacles or an obstacle and a wall, metres. */
    static final double MIN_GAP = 0.12;

    /** The wide profile's smallest arena side, metres. */
    static final double WIDE_MIN_SIDE = 0.7;
    /** The wide profile's doorways and corridors: 12 to 40 cm; a tenth narrower than the robot. */
    static final double MIN_DOOR = 0.12, MAX_DOOR = 0.40;
    /** A sliding box's speed (m/s) and the interval of its moves (s). */
    static final double SLIDE_SPEED = 0.01, SLIDE_EVERY = 4;
    /** How long a sliding box keeps moving, simulated seconds (the criteria's nominal run). */
    static final double SLIDE_UNTIL = 600;
    private static final int WIDE_ATTEMPTS = 60;

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
    private Double maxSide;
    private Profile profile = Profile.CLASSIC;
    private CylinderRange teamCylinders = CylinderRange.TEAM;

    private SplittableRandom random;
    private RobotModel model;
    private Floor floor;

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

    /**
     * How many red cylinders a team world holds, drawn in {@code min..max}. The default is the range
     * the team's targets were set on; another range draws a different world from the same seed.
     */
    public record CylinderRange(int min, int max) {
        /** The team worlds' range (10-14). */
        public static final CylinderRange TEAM = new CylinderRange(10, 14);
        /** The most cylinders a range may ask for (a small arena may hold fewer: the generator stops when the floor is full). */
        public static final int MOST = 60;

        public CylinderRange {
            if (min < 1 || max < min || max > MOST) {
                throw new IllegalArgumentException("cylinders must be a range MIN..MAX with 1 <= MIN <= MAX <= " + MOST
                        + ", got " + min + ".." + max);
            }
        }

        /** {@return the range of "MIN..MAX" or "N"} @throws IllegalArgumentException on anything else */
        public static CylinderRange parse(String text) {
            try {
                int dots = text.indexOf("..");
                return dots < 0 ? new CylinderRange(Integer.parseInt(text.trim()), Integer.parseInt(text.trim()))
                        : new CylinderRange(Integer.parseInt(text.substring(0, dots).trim()),
                                Integer.parseInt(text.substring(dots + 2).trim()));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + text + "' is not a range of cylinders (examples: 10..14, 20..24, 16)");
            }
        }

        @Override
        public String toString() {
            return min + ".." + max;
        }
    }

    /** A team world's cylinders drawn in {@code range} (default {@link CylinderRange#TEAM}: the same draw, so the same worlds). */
    public WorldGenerator cylinders(CylinderRange range) {
        if (experiment != null) {
            throw new IllegalArgumentException("the cylinders' range is for team worlds only");
        }
        this.teamCylinders = range;
        return this;
    }

    /** {@return the name of robot {@code i} (0-based) of a team} */
    public static String teamRobot(int i) {
        return "khepera" + (i + 1);
    }

    /** The range of worlds (default classic). */
    public WorldGenerator profile(Profile p) {
        this.profile = p;
        return this;
    }

    /** The largest arena side, metres (at least 1; default 3, or 4 in the wide profile). */
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
        floor = new Floor(random);
        if (profile == Profile.CLASSIC) {
            return build();
        }
        for (int attempt = 0; attempt < WIDE_ATTEMPTS; attempt++) {
            Generated g = build();
            if (g != null) {
                return g;
            }
        }
        throw new IllegalStateException("no complete " + recipe.id() + " world for seed " + seed + " in " + WIDE_ATTEMPTS
                + " draws (a bug)");
    }

    /** One draw of the world; in the wide profile null when something could not be placed reachably. */
    private Generated build() {
        boolean wide = profile == Profile.WIDE;
        model = experiment == Experiment.OBSTACLE_AVOIDANCE ? RobotModel.MYBOT : RobotModel.KHEPERA;
        // passages at least twice the Khepera's width: a gap the robot's own sensors read as a wall on
        // both sides is a dead end, not a passage
        double gap = Math.max(2 * model.radius() + 0.03, MIN_GAP);
        double minSide = wide && experiment != null ? WIDE_MIN_SIDE : recipe.minSide();
        double largest = maxSide != null ? maxSide : profile.defaultMaxSide();
        double width = round2(floor.uniform(minSide, largest));
        double depth = round2(floor.uniform(minSide, largest));
        floor.clear(width / 2, depth / 2, gap);
        double halfW = floor.halfW(), halfD = floor.halfD();
        String name = recipe.id() + (wide ? "-wide-" : "-gen-") + seed;
        Json j = new Json();
        j.open().field("name", name)
                .field("description", "Generated by `jacabot world generate " + recipe.command() + " --seed " + seed
                        + (wide ? " --profile wide" : "") + "`: a random world for " + recipe.purpose() + ".")
                .raw("arena", "{ \"width\": " + num(width) + ", \"depth\": " + num(depth)
                        + ", \"wallThickness\": 0.02, \"wallHeight\": 0.1 }")
                .raw("basicTimeStep", "8").raw("controlStep", "40").raw("seed", Long.toString(seed));

        List<String> walls = new ArrayList<>();
        List<Reachability.Block> blocks = new ArrayList<>();
        if (wide) {
            partition(walls, blocks);
        }
        boolean needsStorage = recipe.storage();
        boolean needsCharger = recipe.charger();
        double areaRadius = 0.06;
        double[] storage = null, charger = null;
        if (needsStorage) {
            storage = wide ? floor.anywhere(areaRadius, null) : floor.landmark(areaRadius, null);
            if (storage == null) {
                return null;
            }
            floor.keepFree(storage[0], storage[1], areaRadius + gap);
        }
        if (needsCharger) {
            charger = wide ? floor.anywhere(areaRadius, storage) : floor.landmark(areaRadius, storage);
            if (charger == null) {
                return null;
            }
            floor.keepFree(charger[0], charger[1], areaRadius + gap);
        }
        // the robots first, with room around each
        List<String> robots = new ArrayList<>();
        double[] first = null;
        int slots = experiment != null ? 1 : Math.max(recipe.robots(), TEAM_SLOTS);
        for (int i = 0; i < slots; i++) {
            double[] robot = floor.spot(model.radius(), model.radius() + 0.02, 0.05);
            if (robot == null && wide) {
                return null;
            }
            if (robot == null) {
                throw new IllegalStateException("no room for robot " + (i + 1) + " (a bug: arenas hold " + MAX_TEAM + ")");
            }
            double heading = Math.round(random.nextDouble(0, 360));
            first = first == null ? robot : first;
            floor.place(Footprint.circle(robot[0], robot[1], model.radius()));
            floor.keepFree(robot[0], robot[1], model.radius() + gap);
            String battery = experiment != null && needsCharger ? ", \"battery\": 560"
                    : experiment == null ? ", \"battery\": " + num(10 * Math.round(random.nextDouble(45, 70))) : "";
            if (i < recipe.robots()) {
                robots.add("{ \"name\": \"" + (experiment != null ? experiment.robot() : teamRobot(i)) + "\", \"model\": \""
                        + model.name() + "\", \"x\": " + num(robot[0]) + ", \"z\": " + num(robot[1]) + ", \"heading\": "
                        + num(heading) + battery + " }");
            }
        }

        // in the wide profile, what the robot must get to is where it can get (inner walls only so far:
        // the boxes below keep a passage of `gap` around themselves)
        Reachability reach = wide ? Reachability.of(halfW, halfD, blocks, model.radius(), first[0], first[1]) : null;
        if (wide && !(reachable(reach, storage, areaRadius) && reachable(reach, charger, areaRadius))) {
            return null;
        }
        // cylinders before the boxes, so that boxes keep clear of them
        List<String> cylinders = new ArrayList<>();
        List<String> cylinderIds = new ArrayList<>();
        int nCylinders = experiment == null ? teamCylinders.min() + random.nextInt(teamCylinders.max() - teamCylinders.min() + 1)
                : switch (experiment) {
            case OBSTACLE_AVOIDANCE -> 0;
            case OBJECT_PICKING -> 1 + random.nextInt(3);
            default -> 2 + random.nextInt(3);
        };
        for (int i = 0; i < nCylinders; i++) {
            double r = 0.0125;
            double[] p = floor.spot(r, gap, 0.0);
            for (int again = 0; wide && p != null && !reach.canReach(p[0], p[1], reachOf()) && again < 50; again++) {
                p = floor.spot(r, gap, 0.0);
            }
            if (wide && (p == null || !reach.canReach(p[0], p[1], reachOf()))) {
                return null;
            }
            if (p == null) {
                break;
            }
            floor.place(Footprint.circle(p[0], p[1], r));
            floor.keepFree(p[0], p[1], r + gap);
            String id = "red" + (i + 1);
            cylinderIds.add(id);
            cylinders.add("{ \"id\": \"" + id + "\", \"x\": " + num(p[0]) + ", \"z\": " + num(p[1]) + ", \"color\": \"red\" }");
        }

        // obstacles: density = the share of the floor they cover, sparse (1 %) to dense (6 %, three
        // times the default worlds' 2 %; 12 % made mazes of 80 boxes that no controller crossed)
        double density = floor.uniform(MIN_DENSITY, MAX_DENSITY);
        double target = density * width * depth;
        double covered = 0;
        List<String> boxes = new ArrayList<>();
        List<double[]> boxSpots = new ArrayList<>();
        for (int attempt = 0; attempt < 400 && covered < target; attempt++) {
            double sx = round3(floor.uniform(0.04, 0.10));
            double sz = random.nextInt(3) == 0 ? round3(floor.uniform(0.04, 0.12)) : sx;
            double h = random.nextInt(2) == 0 ? 0 : Math.round(random.nextDouble(0, 90));
            double x = round3(floor.uniform(-halfW + gap + 0.06, halfW - gap - 0.06));
            double z = round3(floor.uniform(-halfD + gap + 0.06, halfD - gap - 0.06));
            Footprint f = Footprint.rectangle(x, z, sx, sz, h);
            Footprint grown = Footprint.rectangle(x, z, sx + 2 * gap, sz + 2 * gap, h);
            if (!grown.inside(halfW, halfD) || !floor.isClear(grown, f)) {
                continue;
            }
            floor.place(f);
            boxSpots.add(new double[] {x, z, sx, sz, h});
            boolean movable = random.nextInt(5) == 0;
            String id = "box" + (boxes.size() + 1);
            boxes.add("{ \"id\": \"" + id + "\", \"x\": " + num(x) + ", \"z\": " + num(z) + ", \"size\": "
                    + (sx == sz ? num(sx) : "[" + num(sx) + ", " + num(sz) + "]")
                    + (h != 0 ? ", \"heading\": " + num(h) : "") + (movable ? ", \"movable\": true, \"mass\": 0.3" : "") + " }");
            covered += sx * sz;
        }

        List<String> events = new ArrayList<>(experiment == null ? List.of() : ScriptedFaults.draw(experiment, model, floor, random, boxSpots, cylinderIds));
        if (wide) {
            slidingBoxes(boxes, events);
            j.array("walls", walls);
        }
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
        WorldSpec spec;
        try {
            spec = WorldFileReader.parse(json, name + ".json");
        } catch (WorldFileException e) {
            throw new IllegalStateException("the generator made an invalid world (a bug): " + e.getMessage(), e);
        }
        return !wide || everythingReachable(spec) ? new Generated(json, spec) : null;
    }

    /** The distance from a cylinder's centre within which the robot's centre must get to take it. */
    private double reachOf() {
        return model.radius() + 0.03;
    }

    /** Whether the robot's centre can get into the area (null: no area). */
    private static boolean reachable(Reachability reach, double[] area, double radius) {
        return area == null || reach.canReach(area[0], area[1], radius / 2);
    }

    /** The wide profile's last check, on the loaded world with its boxes: every robot, cylinder and area reachable. */
    private boolean everythingReachable(WorldSpec spec) {
        RobotSpec r0 = spec.robots().get(0);
        Reachability reach = Reachability.of(spec, model.radius(), r0.x(), r0.z());
        for (RobotSpec r : spec.robots()) {
            if (!reach.canReach(r.x(), r.z(), 0.02)) {
                return false;
            }
        }
        for (CylinderSpec c : spec.cylinders()) {
            if (!reach.canReach(c.x(), c.z(), reachOf())) {
                return false;
            }
        }
        for (AreaSpec a : new AreaSpec[] {spec.storage(), spec.charger()}) {
            if (a != null && !reach.canReach(a.x(), a.z(), a.radius() / 2)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The wide profile's inner wall, in seven arenas of ten (of at least 1 m): across the longer side,
     * thin with one doorway or 20 to 60 cm thick with a corridor through it, 12 to 40 cm wide; in a
     * tenth of them the passage is narrower than the robot, closing a room it cannot enter.
     */
    private void partition(List<String> walls, List<Reachability.Block> blocks) {
        double kind = random.nextDouble();
        double halfW = floor.halfW(), halfD = floor.halfD();
        if (kind < 0.3 || experiment == null || Math.max(halfW, halfD) < 0.5) {
            return;
        }
        boolean acrossX = halfW >= halfD; // the wall stands at x = at and spans z
        double along = acrossX ? halfW : halfD, span = acrossX ? halfD : halfW;
        double thickness = kind < 0.65 ? 0.02 : round3(floor.uniform(0.2, Math.min(0.6, along * 0.5)));
        double at = round3(floor.uniform(-along * 0.4, along * 0.4));
        // even millimetres, so that a segment's centre and length are exact in the file's four decimals
        double door = 2 * round3((kind < 0.93 ? floor.uniform(MIN_DOOR, MAX_DOOR) : floor.uniform(0.03, 2 * model.radius() - 0.01)) / 2);
        double centre = round3(floor.uniform(-span + door / 2 + 0.05, span - door / 2 - 0.05));
        double[][] parts = {{-span, centre - door / 2}, {centre + door / 2, span}};
        for (double[] part : parts) {
            double length = part[1] - part[0];
            if (length < 0.01) {
                continue;
            }
            double mid = (part[0] + part[1]) / 2;
            double x = acrossX ? at : mid, z = acrossX ? mid : at;
            double sx = acrossX ? thickness : length, sz = acrossX ? length : thickness;
            floor.place(Footprint.rectangle(x, z, sx, sz, 0));
            blocks.add(new Reachability.Block(x, z, sx, sz, 0));
            walls.add("{ \"id\": \"wall" + (walls.size() + 1) + "\", \"x\": " + Json.num4(x) + ", \"z\": " + Json.num4(z)
                    + ", \"size\": [" + Json.num4(sx) + ", " + Json.num4(sz) + "], \"height\": 0.1 }");
        }
    }

    /**
     * Up to two boxes that slide back and forth at {@link #SLIDE_SPEED} along a lane of 20 to 60 cm
     * whose whole sweep keeps the generator's passage from everything, so no passage ever closes;
     * scripted as a move every {@link #SLIDE_EVERY} s (physics pushes what stands in the way).
     */
    private void slidingBoxes(List<String> boxes, List<String> events) {
        int n = random.nextInt(3);
        double halfW = floor.halfW(), halfD = floor.halfD(), gap = floor.gap();
        for (int m = 0; m < n; m++) {
            for (int attempt = 0; attempt < 100; attempt++) {
                double size = round3(floor.uniform(0.04, 0.08));
                boolean alongX = random.nextBoolean();
                double travel = round3(floor.uniform(0.2, 0.6));
                double x = round3(floor.uniform(-halfW + gap, halfW - gap));
                double z = round3(floor.uniform(-halfD + gap, halfD - gap));
                double mx = alongX ? x + travel / 2 : x, mz = alongX ? z : z + travel / 2;
                double lx = alongX ? travel + size : size, lz = alongX ? size : travel + size;
                Footprint lane = Footprint.rectangle(mx, mz, lx, lz, 0);
                Footprint grown = Footprint.rectangle(mx, mz, lx + 2 * gap, lz + 2 * gap, 0);
                if (!grown.inside(halfW, halfD) || !floor.isClear(grown, lane)) {
                    continue;
                }
                floor.place(lane);
                String id = "box" + (boxes.size() + 1);
                boxes.add("{ \"id\": \"" + id + "\", \"x\": " + num(x) + ", \"z\": " + num(z) + ", \"size\": " + num(size) + " }");
                for (double t = SLIDE_EVERY; t <= SLIDE_UNTIL; t += SLIDE_EVERY) {
                    double phase = (t * SLIDE_SPEED) % (2 * travel);
                    double offset = round3(phase <= travel ? phase : 2 * travel - phase);
                    events.add("{ \"at\": " + num(t) + ", \"do\": \"move\", \"object\": \"" + id + "\", \"x\": "
                            + num(round3(alongX ? x + offset : x)) + ", \"z\": " + num(round3(alongX ? z : z + offset)) + " }");
                }
                break;
            }
        }
    }
}
