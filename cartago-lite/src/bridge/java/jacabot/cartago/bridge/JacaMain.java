package jacabot.cartago.bridge;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.runtime.MasLauncher;
import java.nio.file.Path;

/**
 * Runs a JaCa project whose artifacts are already on the class path (a Gradle project built
 * against the published jars, see examples/gradle-project): {@code JacaMain FILE.mas2j [SEED]}.
 * Exit codes: 0 after {@code .stopMAS}, 2 for a bad project (one line on stderr).
 */
public final class JacaMain {
    private JacaMain() {
    }

    public static void main(String[] args) throws InterruptedException {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: JacaMain FILE.mas2j [SEED]");
            System.exit(2);
        }
        try {
            long seed = args.length == 2 ? Long.parseLong(args[1]) : 0;
            LocalMAS mas = new MasLauncher(System.out, seed, false).load(Path.of(args[0]));
            mas.runThreads();
        } catch (NumberFormatException e) {
            System.err.println("SEED must be a whole number, got " + args[1]);
            System.exit(2);
        } catch (MasLauncher.UserError e) {
            System.err.println(e.getMessage());
            System.exit(2);
        }
        System.exit(0);
    }
}
