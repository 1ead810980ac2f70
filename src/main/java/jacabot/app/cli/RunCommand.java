package jacabot.app.cli;

import jacabot.agent.runtime.MasLauncher;
import java.nio.file.Path;
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

    @Option(names = "--stats", description = "print the number of reasoning cycles on stderr at the end")
    private boolean stats;

    @Override
    public Integer call() throws InterruptedException {
        try {
            var launcher = new MasLauncher(System.out, seed, stepping);
            var mas = launcher.load(file);
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
            return 0;
        } catch (MasLauncher.UserError e) {
            System.err.println(e.getMessage());
            return 2;
        }
    }
}
