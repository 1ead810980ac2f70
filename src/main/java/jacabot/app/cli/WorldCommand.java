package jacabot.app.cli;

import jacabot.app.world.WorldGenerator;
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

    /** {@code jacabot world generate EXPERIMENT --seed N}: a random valid world, the same for the same seed. */
    @Command(name = "generate", mixinStandardHelpOptions = true,
            description = {"Makes a random world for an experiment: arena 1-3 m a side, sparse to dense obstacles, storage "
                    + "point and charger in a corner or along a wall, red cylinders, scripted faults at random times.",
                    "The same experiment and seed give the same file. The world is checked with the loader."})
    static final class Generate implements Callable<Integer> {
        @CommandLine.Spec
        private CommandLine.Model.CommandSpec spec;

        @Parameters(index = "0", paramLabel = "EXPERIMENT", converter = ExperimentCommand.ExperimentConverter.class,
                description = "obstacle-avoidance | object-picking | navigation | suspend-resume | tidy-up (or 1-5)")
        private Experiment experiment;

        @Option(names = "--seed", paramLabel = "N", required = true, description = "the generator's seed (also the world's seed)")
        private long seed;

        @Option(names = "--out", paramLabel = "FILE", description = "where to write the world (default: standard output)")
        private Path out;

        @Option(names = "--max-side", paramLabel = "M", description = "largest arena side in metres, >= 1 (default ${DEFAULT-VALUE})")
        private double maxSide = 3.0;

        @Override
        public Integer call() throws IOException {
            if (!(maxSide >= 1)) {
                throw new UserError("--max-side must be at least 1 (metres), got " + maxSide);
            }
            String json = new WorldGenerator(experiment, seed).maxSide(maxSide).generate().json();
            if (out == null) {
                PrintWriter o = spec.commandLine().getOut();
                o.print(json);
                o.flush();
            } else {
                if (out.getParent() != null) {
                    Files.createDirectories(out.getParent());
                }
                Files.writeString(out, json, StandardCharsets.UTF_8);
            }
            return 0;
        }
    }
}
