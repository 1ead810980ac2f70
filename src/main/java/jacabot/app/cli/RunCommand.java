package jacabot.app.cli;

import jacabot.agent.runtime.MasLauncher;
import jacabot.cartago.bridge.ProjectClasses;
import jacabot.cartago.bridge.ProjectClasspath;
import jacabot.cartago.bridge.SourceCompiler;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code jacabot run FILE}: runs a Jason project (.mas2j) or a single agent (.asl). */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = {"Runs a Jason project (.mas2j) or one agent (.asl, named after the file) until .stopMAS.",
                "Console lines are printed as Jason prints them: [agent] text."})
final class RunCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", description = "a .mas2j project or an .asl agent")
    private Path file;

    @Option(names = "--seed", description = "seed of the agents' random generators (default ${DEFAULT-VALUE})")
    private long seed = 0;

    @Option(names = "--step", description = "deterministic stepping on one thread instead of a thread per agent")
    private boolean stepping;

    @Option(names = "--classpath", paramLabel = "PATH",
            description = "more class path entries for the project's artifacts (jars, folders, folder/* for its jars; "
                    + "separated by the platform's path separator, or the option repeated)")
    private List<String> classpath = new ArrayList<>();

    @Option(names = "--stats", description = "print the number of reasoning cycles on stderr at the end")
    private boolean stats;

    @picocli.CommandLine.Mixin
    private InspectorOptions inspectorOptions = new InspectorOptions();

    @Override
    public Integer call() throws Exception {
        try {
            // the project's artifacts: classpath: entries, --classpath, Java sources beside the .mas2j
            var entries = new ArrayList<Path>();
            classpath.forEach(c -> Arrays.stream(c.split(File.pathSeparator)).filter(e -> !e.isEmpty()).map(Path::of).forEach(entries::add));
            var classes = ProjectClasses.prepare(file.toString().endsWith(".mas2j") ? file : null, entries);
            classes.classpath().warnings().forEach(System.err::println);
            Thread.currentThread().setContextClassLoader(classes.loader());
            var launcher = new MasLauncher(System.out, seed, stepping);
            var mas = launcher.load(file);
            // off by default: console programs end in moments; --inspector shows their minds
            var inspector = inspectorOptions.start(false, "jacabot run " + file, System.out);
            AutoCloseable sampling = () -> {
            };
            if (inspector != null) {
                var watches = new java.util.ArrayList<jacabot.app.inspector.AgentWatch>();
                for (String name : mas.agentNames()) {
                    watches.add(jacabot.app.inspector.AgentWatch.attach(inspector, mas.agent(name), null));
                }
                sampling = jacabot.app.inspector.AgentWatch.sampleEvery(watches, 200);
            }
            if (stepping) {
                mas.runStepping();
            } else {
                mas.runThreads();
            }
            if (stats) {
                long cycles = 0;
                for (String name : mas.agentNames()) {
                    cycles += mas.agent(name).cycles();
                }
                System.err.println("cycles " + cycles);
            }
            sampling.close();
            if (inspector != null) {
                inspectorOptions.linger(inspector, System.out);
                inspector.close();
            }
            return 0;
        } catch (ProjectClasspath.Problem e) {
            System.err.println(e.getMessage());
            return 2;
        } catch (SourceCompiler.CompileError e) {
            e.lines().forEach(System.err::println);
            return 2;
        } catch (MasLauncher.UserError e) {
            System.err.println(e.getMessage());
            return 2;
        }
    }
}
