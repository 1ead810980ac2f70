package jacabot.app.sweep;

import jacabot.app.world.WorldGenerator;
import jacabot.app.world.WorldGenerator.Profile;
import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The runs of a sweep, in a fixed order (experiment, world, seed, controller), so that shard I of N
 * (every N-th job from the I-th) is the same list on every machine.
 */
public final class SweepPlan {
    /** A world for an experiment: its name, file (null if only in memory) and checked spec, or the loader's message. */
    public record World(Experiment experiment, String name, Path file, WorldSpec spec, String problem) {
    }

    private SweepPlan() {
    }

    /**
     * {@return K generated worlds per experiment (generator seeds 1..K)}
     *
     * @param writeTo a directory to write them to (for replays), or null
     */
    public static List<World> generated(List<Experiment> experiments, int k, double maxSide, Path writeTo) throws IOException {
        return generated(experiments, firstSeeds(k), Profile.CLASSIC, maxSide, writeTo);
    }

    /** {@return generator seeds 1..k} */
    public static List<Long> firstSeeds(int k) {
        List<Long> worldSeeds = new ArrayList<>();
        for (long seed = 1; seed <= k; seed++) {
            worldSeeds.add(seed);
        }
        return worldSeeds;
    }

    /** {@return generated worlds of these generator seeds for each experiment (e.g. 51..100: worlds kept out of tuning)} */
    public static List<World> generated(List<Experiment> experiments, List<Long> worldSeeds, double maxSide, Path writeTo)
            throws IOException {
        return generated(experiments, worldSeeds, Profile.CLASSIC, maxSide, writeTo);
    }

    /**
     * {@return generated worlds of a profile and these generator seeds for each experiment}
     *
     * @param maxSide the largest arena side in metres, or null for the profile's own
     */
    public static List<World> generated(List<Experiment> experiments, List<Long> worldSeeds, Profile profile, Double maxSide,
            Path writeTo) throws IOException {
        List<World> out = new ArrayList<>();
        for (Experiment e : experiments) {
            for (long seed : worldSeeds) {
                WorldGenerator generator = new WorldGenerator(e, seed).profile(profile);
                var g = (maxSide == null ? generator : generator.maxSide(maxSide)).generate();
                Path file = null;
                if (writeTo != null) {
                    Files.createDirectories(writeTo);
                    file = writeTo.resolve(g.spec().name() + ".json");
                    Files.writeString(file, g.json(), StandardCharsets.UTF_8);
                }
                out.add(new World(e, g.spec().name(), file, g.spec(), null));
            }
        }
        return out;
    }

    /**
     * {@return whether a world file's name starts with no experiment's id, the team's included: such a
     * file belongs to whichever single experiment (or the team) a sweep of a folder is for}
     */
    public static boolean namedForNoExperiment(String fileName) {
        return Stream.of(Experiment.values()).noneMatch(x -> fileName.startsWith(x.id()))
                && !fileName.startsWith(WorldGenerator.TEAM_DELIVERY);
    }

    /**
     * {@return the world files of a directory (and its subdirectories) for each experiment: those whose
     * name starts with the experiment's id; when only one experiment is swept, also those that start
     * with no experiment's id nor the team experiment's}. A file the loader rejects stays in the list with its message.
     */
    public static List<World> directory(List<Experiment> experiments, Path dir) throws IOException {
        List<Path> files;
        try (Stream<Path> s = Files.walk(dir)) {
            files = s.filter(p -> Files.isRegularFile(p) && p.getFileName().toString().endsWith(".json")).sorted().toList();
        }
        List<World> out = new ArrayList<>();
        for (Experiment e : experiments) {
            for (Path f : files) {
                String name = f.getFileName().toString();
                boolean mine = name.startsWith(e.id());
                if (mine || namedForNoExperiment(name) && experiments.size() == 1) {
                    String label = name.substring(0, name.length() - 5);
                    try {
                        out.add(new World(e, label, f, WorldFileReader.read(f), null));
                    } catch (WorldFileException ex) {
                        out.add(new World(e, label, f, null, ex.getMessage()));
                    }
                }
            }
        }
        return out;
    }

    /** {@return the jobs: every world x seed x controller, then the shard's slice (shard in 1..shards)} */
    public static List<SweepJob> jobs(List<World> worlds, List<Long> seeds, List<String> controllers, int shard, int shards) {
        List<SweepJob> all = new ArrayList<>();
        for (World w : worlds) {
            for (long seed : seeds) {
                for (String c : controllers) {
                    if (!c.equals(SweepJob.AGENT) && !w.experiment().hasBaseline()) {
                        continue; // tidy-up: composed of the agents' skills, no C program to compare with
                    }
                    all.add(new SweepJob(w.experiment(), c, w.name(), w.file(), w.spec(), w.problem(), seed));
                }
            }
        }
        List<SweepJob> mine = new ArrayList<>();
        for (int i = 0; i < all.size(); i++) {
            if (i % shards == shard - 1) {
                mine.add(all.get(i));
            }
        }
        return mine;
    }

    /** {@return seeds from "1..5", "3", or "1,4,9"} @throws IllegalArgumentException on anything else */
    public static List<Long> seeds(String text) {
        List<Long> out = new ArrayList<>();
        try {
            for (String part : text.split(",")) {
                String p = part.trim();
                int dots = p.indexOf("..");
                if (dots >= 0) {
                    long from = Long.parseLong(p.substring(0, dots).trim());
                    long to = Long.parseLong(p.substring(dots + 2).trim());
                    if (to < from || to - from > 100_000) {
                        throw new IllegalArgumentException("bad seed range '" + p + "'");
                    }
                    for (long s = from; s <= to; s++) {
                        out.add(s);
                    }
                } else {
                    out.add(Long.parseLong(p));
                }
            }
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("bad seeds '" + text + "' (examples: 1..5, 3, 1,4,9)");
        }
        return out;
    }
}
