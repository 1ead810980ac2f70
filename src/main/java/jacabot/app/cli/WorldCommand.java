package jacabot.app.cli;

import jacabot.app.world.WorldGenerator;
import jacabot.app.world.WorldGenerator.Profile;
import jacabot.robot.Experiment;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code jacabot world ...}: world files (generate, view, render). */
@Command(name = "world", mixinStandardHelpOptions = true, description = "World files: generate random ones, view, render.",
        subcommands = {WorldCommand.Generate.class, WorldViewCommands.View.class, WorldViewCommands.Render.class})
final class WorldCommand implements Runnable {
    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    /** {@code jacabot world generate EXPERIMENT [--robots N] --seed S}: a random valid world, the same for the same seed. */
    @Command(name = "generate", mixinStandardHelpOptions = true,
            description = {"Makes a random world for an experiment: arena 1-3 m a side, sparse to dense obstacles, storage "
                    + "point and charger in a corner or along a wall, red cylinders, scripted faults at random times.",
                    "team-delivery: N Kheperas (khepera1..N) placed apart, 10-14 cylinders, one storage point, one charger, "
                    + "arena 1.5-3 m, no faults; one seed gives teams of 1 to 4 the same layout.",
                    "The same experiment and seed give the same file. The world is checked with the loader."})
    static final class Generate implements Callable<Integer> {
        @CommandLine.Spec
        private CommandLine.Model.CommandSpec spec;

        @Parameters(index = "0", paramLabel = "EXPERIMENT",
                description = "obstacle-avoidance | object-picking | navigation | suspend-resume | tidy-up (or 1-5) | team-delivery")
        private String experiment;

        @Option(names = "--robots", paramLabel = "N", description = "team-delivery only: the team's size, 1-"
                + WorldGenerator.MAX_TEAM + " (default ${DEFAULT-VALUE})")
        private int robots = 2;

        @Option(names = "--cylinders", paramLabel = "MIN..MAX", description = "team-delivery only: how many red cylinders, "
                + "drawn in MIN..MAX (default 10..14, the range the team's targets were set on; another range gives "
                + "another world for the same seed)")
        private String cylinders;

        @Option(names = "--seed", paramLabel = "N", required = true, description = "the generator's seed (also the world's seed)")
        private long seed;

        @Option(names = "--out", paramLabel = "FILE", description = "where to write the world (default: standard output)")
        private Path out;

        @Option(names = "--max-side", paramLabel = "M", description = "largest arena side in metres, >= 1 (default 3, wide profile 4)")
        private Double maxSide;

        @Option(names = "--profile", paramLabel = "P", description = "classic (1-3 m, open, the range first measured) or wide "
                + "(0.7-4 m, an inner wall with a doorway or a corridor, areas anywhere, sliding boxes) (default ${DEFAULT-VALUE})")
        private String profile = "classic";

        @Override
        public Integer call() throws IOException {
            if (maxSide != null && !(maxSide >= 1)) {
                throw new UserError("--max-side must be at least 1 (metres), got " + maxSide);
            }
            Profile worldProfile;
            try {
                worldProfile = Profile.parse(profile);
            } catch (IllegalArgumentException e) {
                throw new UserError(e.getMessage());
            }
            WorldGenerator generator;
            if (experiment.equals(WorldGenerator.TEAM_DELIVERY)) {
                if (robots < 1 || robots > WorldGenerator.MAX_TEAM) {
                    throw new UserError("--robots must be 1 to " + WorldGenerator.MAX_TEAM + ", got " + robots);
                }
                generator = WorldGenerator.team(robots, seed);
                if (cylinders != null) {
                    generator.cylinders(cylinderRange(cylinders));
                }
            } else {
                Experiment e = Experiment.parse(experiment).orElseThrow(() -> new UserError("unknown experiment '"
                        + experiment + "' (expected one of obstacle-avoidance, object-picking, navigation, suspend-resume, "
                        + "tidy-up, " + WorldGenerator.TEAM_DELIVERY + ")"));
                if (spec.commandLine().getParseResult().hasMatchedOption("--robots")) {
                    throw new UserError("--robots is for " + WorldGenerator.TEAM_DELIVERY + " only; " + e.id() + " has one robot");
                }
                if (cylinders != null) {
                    throw new UserError("--cylinders is for " + WorldGenerator.TEAM_DELIVERY + " only");
                }
                generator = new WorldGenerator(e, seed);
            }
            generator.profile(worldProfile);
            String json = (maxSide == null ? generator : generator.maxSide(maxSide)).generate().json();
            if (out == null) {
                PrintWriter o = spec.commandLine().getOut();
                o.print(json);
                o.flush();
            } else {
                OutPlace.file("--out", out);
                try {
                    Files.writeString(out, json, StandardCharsets.UTF_8);
                } catch (IOException e) {
                    throw OutPlace.cannotWrite("--out", out, e);
                }
            }
            return 0;
        }

        /** {@return the range of a --cylinders value} @throws UserError on a bad one */
        static WorldGenerator.CylinderRange cylinderRange(String text) {
            try {
                return WorldGenerator.CylinderRange.parse(text);
            } catch (IllegalArgumentException e) {
                throw new UserError("--cylinders: " + e.getMessage());
            }
        }
    }
}
