package jacabot.app.cli;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.cartago.CartagoException;
import jacabot.robot.Experiment;
import jacabot.app.run.LockstepRun;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.Robot;
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

    @Option(names = "--speed", paramLabel = "X", description = "with the viewer: real time x this factor (default ${DEFAULT-VALUE})")
    private double speed = 1;

    @Option(names = "--seed", paramLabel = "N", description = "seed of the world and the agent (default: the world file's)")
    private Long seed;

    @Option(names = "--duration", paramLabel = "T", description = "simulated time: 90s, 10m, ... (default ${DEFAULT-VALUE})")
    private String duration = "10m";

    @Option(names = "--world", paramLabel = "FILE", description = "the world file (default worlds/NAME.json)")
    private Path world;

    @Option(names = "--agent", paramLabel = "FILE", description = "the agent (default: the packaged agents/src/main/asl/NAME.asl)")
    private Path agent;

    @Option(names = "--baseline", description = "run the procedural baseline controller (the thesis' C program) instead of the agent")
    private boolean baseline;

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
        var missing = jacabot.app.world.Landmarks.missing(experiment, spec, worldFile.toString());
        if (missing.isPresent()) { // before anything starts, agent and baseline alike
            System.err.println(missing.get());
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
        SimWorld simWorld = SimWorld.of(spec);
        if (baseline) {
            System.out.println("World " + worldFile + ", seed " + runSeed + ", " + duration
                    + " of simulated time, procedural baseline, headless.");
            long t0 = System.nanoTime();
            var run = jacabot.robot.baseline.BaselineRunner.execute(worldFile, experiment, runSeed, seconds);
            report(run.summary(), run.recorder(), outDir, (System.nanoTime() - t0) / 1e9, -1);
            return 0;
        }
        boolean viewer = !headless && !lockstep && !java.awt.GraphicsEnvironment.isHeadless();
        if (viewer) {
            if (!(speed > 0)) {
                System.err.println("error: --speed must be positive, got " + speed);
                return 2;
            }
            System.out.println("World " + worldFile + ", seed " + runSeed + ", real time x" + speed
                    + " with the viewer (close the window to stop).");
            return runWithViewer(simWorld, source, sourceName, runSeed, seconds);
        }
        System.out.println("World " + worldFile + ", seed " + runSeed + ", " + duration + " of simulated time, lockstep, headless.");
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
        var recorder = jacabot.robot.run.RunRecorder.attach(simWorld, robot.name());
        long start = System.nanoTime();
        long[] nextReport = {10_000};
        run.onStep(data -> {
            if (data.simTimeMs() >= nextReport[0]) {
                nextReport[0] += 10_000;
                double wall = (System.nanoTime() - start) / 1e9;
                var now = recorder.summary("agent");
                System.out.printf("  t=%6.1f s  %5.0fx real time  picked %d  delivered %d  battery %s%n",
                        data.simTimeMs() / 1000.0, data.simTimeMs() / 1000.0 / Math.max(wall, 1e-6), now.picks(),
                        now.deliveries(), !robot.hasBattery() ? "-" : String.format("%.0f J", robot.getBattery().energy()));
            }
        });
        var result = run.runFor(seconds);
        if (result.steps() * spec.controlStep() < seconds * 1000 - spec.controlStep()) {
            System.out.println("The link ended early:");
            result.linkLog().forEach(l -> System.out.println("  " + l));
        }
        double wall = (System.nanoTime() - start) / 1e9;
        report(recorder.summary("agent"), recorder, outDir, wall, run.cycles());
        Files.write(outDir.resolve("link-log.txt"), new ArrayList<>(result.controllerLog()));
        return 0;
    }

    /** Writes the summary (JSON and text), the event log and the trajectory, and prints them. */
    private static void report(jacabot.robot.run.RunSummary summary, jacabot.robot.run.RunRecorder recorder, Path outDir,
            double wallSeconds, long cycles) throws IOException {
        Files.createDirectories(outDir);
        summary.writeJson(outDir.resolve("summary.json"));
        Files.writeString(outDir.resolve("summary.txt"), summary.toText());
        Files.writeString(outDir.resolve("event-log.txt"), summary.eventLog());
        recorder.writePng(outDir.resolve("trajectory.png"), 800, 800);
        System.out.println();
        System.out.print(summary.toText());
        System.out.printf("%.0f s simulated in %.1f s (%.0fx real time)%s.%n", summary.duration(), wallSeconds,
                summary.duration() / Math.max(wallSeconds, 1e-9), cycles >= 0 ? ", " + cycles + " reasoning cycles" : "");
        System.out.println("Written: " + outDir.resolve("summary.json") + ", summary.txt, event-log.txt, trajectory.png");
    }

    /** Real time with the Swing viewer, the agent running free as in the thesis. */
    private int runWithViewer(SimWorld simWorld, String source, String sourceName, long runSeed, double seconds)
            throws InterruptedException {
        try (var run = new jacabot.app.run.RealTimeRun(simWorld, experiment, source, sourceName, runSeed, speed, System.out)) {
            run.start();
            var closed = new java.util.concurrent.CountDownLatch(1);
            javax.swing.SwingUtilities.invokeLater(() -> {
                javax.swing.JFrame frame = jacabot.sim.viewer.WorldViewer.open(run.runner());
                frame.setDefaultCloseOperation(javax.swing.WindowConstants.DISPOSE_ON_CLOSE);
                frame.addWindowListener(new java.awt.event.WindowAdapter() {
                    @Override
                    public void windowClosed(java.awt.event.WindowEvent e) {
                        closed.countDown();
                    }
                });
            });
            while (!closed.await(200, java.util.concurrent.TimeUnit.MILLISECONDS)) {
                if (simWorld.time() >= seconds) {
                    break;
                }
            }
            run.runner().stop();
        } catch (AslSyntaxException e) {
            System.err.println(e.getMessage());
            return 2;
        } catch (CartagoException e) {
            System.err.println("error: cannot make the middleware: " + e.getMessage());
            return 1;
        }
        System.out.printf("Stopped at t=%.1f s of simulated time.%n", simWorld.time());
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
