package jacabot.experiments.cli;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.cartago.CartagoException;
import jacabot.experiments.run.Experiment;
import jacabot.experiments.run.LockstepRun;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.Robot;
import jacabot.sim.viewer.PngRenderer;
import jacabot.sim.world.WorldSpec;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.TypeConversionException;

/** {@code jacabot experiment NAME}: runs one of the four experiments of the thesis' Chapter 4. */
@Command(name = "experiment", mixinStandardHelpOptions = true,
        description = {"Runs an experiment of Chapter 4 with the agent in the loop: obstacle-avoidance, "
                + "object-picking, navigation, suspend-resume (or 1-4).",
                "Headless runs go in lockstep as fast as possible and end with a summary and a PNG of the trajectory."})
final class ExperimentCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "NAME", converter = ExperimentConverter.class,
            description = "obstacle-avoidance | object-picking | navigation | suspend-resume")
    private Experiment experiment;

    @Option(names = "--headless", description = "no viewer: lockstep, as fast as possible (the default without a display)")
    private boolean headless;

    @Option(names = "--lockstep", description = "advance the world only when the agent is idle (always on when headless)")
    private boolean lockstep;

    @Option(names = "--seed", paramLabel = "N", description = "seed of the world and the agent (default: the world file's)")
    private Long seed;

    @Option(names = "--duration", paramLabel = "T", description = "simulated time: 90s, 10m, ... (default ${DEFAULT-VALUE})")
    private String duration = "10m";

    @Option(names = "--world", paramLabel = "FILE", description = "the world file (default worlds/NAME.json)")
    private Path world;

    @Option(names = "--agent", paramLabel = "FILE", description = "the agent (default: the packaged agents/src/main/asl/NAME.asl)")
    private Path agent;

    @Option(names = "--out", paramLabel = "DIR", description = "where the summary and the PNG go (default runs/NAME-SEED)")
    private Path out;

    @Override
    public Integer call() throws Exception {
        double seconds;
        try {
            seconds = parseDuration(duration);
        } catch (IllegalArgumentException e) {
            System.err.println("error: " + e.getMessage());
            return 2;
        }
        Path worldFile = world != null ? world : Path.of(experiment.worldFile());
        WorldSpec spec;
        try {
            spec = WorldFileReader.read(worldFile);
        } catch (WorldFileException e) {
            System.err.println(e.getMessage());
            return 2;
        }
        long runSeed = seed != null ? seed : spec.seed();
        spec = new WorldSpec(spec.name(), spec.arena(), spec.basicTimeStep(), spec.controlStep(), runSeed, spec.sensorNoise(),
                spec.walls(), spec.boxes(), spec.cylinders(), spec.storage(), spec.charger(), spec.robots(), spec.events());
        String source;
        String sourceName;
        if (agent != null) {
            if (!Files.isRegularFile(agent)) {
                System.err.println(agent + ": no such file");
                return 2;
            }
            source = Files.readString(agent, StandardCharsets.UTF_8);
            sourceName = agent.toString();
        } else {
            try (InputStream in = ExperimentCommand.class.getResourceAsStream(experiment.agentResource())) {
                source = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            }
            sourceName = "agents/src/main/asl/" + experiment.id() + ".asl";
        }
        Path outDir = out != null ? out : Path.of("runs", experiment.id() + "-" + runSeed);
        System.out.println("Experiment " + experiment.number() + " (" + experiment + "): " + experiment.summary() + ".");
        System.out.println("World " + worldFile + ", seed " + runSeed + ", " + duration + " of simulated time, lockstep, headless.");
        SimWorld simWorld = SimWorld.of(spec);
        LockstepRun run;
        try {
            run = new LockstepRun(simWorld, null, experiment, source, sourceName, runSeed, System.out);
        } catch (AslSyntaxException e) {
            System.err.println(e.getMessage());
            return 2;
        } catch (CartagoException e) {
            System.err.println("error: cannot make the middleware: " + e.getMessage());
            return 1;
        }
        Robot robot = simWorld.robots().get(0);
        long start = System.nanoTime();
        long[] nextReport = {10_000};
        run.onStep(data -> {
            if (data.simTimeMs() >= nextReport[0]) {
                nextReport[0] += 10_000;
                double wall = (System.nanoTime() - start) / 1e9;
                System.out.printf("  t=%6.1f s  %5.0fx real time  battery %s%n", data.simTimeMs() / 1000.0,
                        data.simTimeMs() / 1000.0 / Math.max(wall, 1e-6),
                        !robot.hasBattery() ? "-" : String.format("%.0f J", robot.getBattery().energy()));
            }
        });
        var result = run.runFor(seconds);
        if (result.steps() * spec.controlStep() < seconds * 1000 - spec.controlStep()) {
            System.out.println("The link ended early:");
            result.linkLog().forEach(l -> System.out.println("  " + l));
        }
        double wall = (System.nanoTime() - start) / 1e9;
        Files.createDirectories(outDir);
        Path png = outDir.resolve("trajectory.png");
        PngRenderer.write(simWorld, png, 800, 800);
        Files.write(outDir.resolve("event-log.txt"), new ArrayList<>(result.controllerLog()));
        System.out.printf("Done: %.0f s simulated in %.1f s (%.0fx real time), %d steps, %d reasoning cycles.%n",
                result.steps() * spec.controlStep() / 1000.0, wall, result.steps() * spec.controlStep() / 1000.0 / wall,
                result.steps(), run.cycles());
        System.out.println("Trajectory: " + png + ", event log: " + outDir.resolve("event-log.txt"));
        return 0;
    }

    static double parseDuration(String text) {
        var m = java.util.regex.Pattern.compile("(\\d+(?:\\.\\d+)?)\\s*(ms|s|m|min|h)?").matcher(text.trim());
        if (!m.matches()) {
            throw new IllegalArgumentException("bad duration '" + text + "' (examples: 90s, 10m, 1h)");
        }
        double v = Double.parseDouble(m.group(1));
        String unit = m.group(2) == null ? "s" : m.group(2);
        switch (unit) {
            case "ms": return v / 1000;
            case "m":
            case "min": return v * 60;
            case "h": return v * 3600;
            default: return v;
        }
    }

    static final class ExperimentConverter implements ITypeConverter<Experiment> {
        @Override
        public Experiment convert(String value) {
            return Experiment.parse(value).orElseThrow(() -> new TypeConversionException("unknown experiment '" + value
                    + "' (expected one of obstacle-avoidance, object-picking, navigation, suspend-resume)"));
        }
    }
}
