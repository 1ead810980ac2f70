package jacabot.app.cli;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.runtime.MasLauncher;
import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.app.Installation;
import jacabot.app.console.ConsoleLog;
import jacabot.app.inspector.MindWatch;
import jacabot.app.run.AgentWatch;
import jacabot.app.run.ExperimentMatch;
import jacabot.app.run.RealTimeRun;
import jacabot.app.run.TlsRelay;
import jacabot.cartago.bridge.ProjectClasses;
import jacabot.cartago.bridge.ProjectClasspath;
import jacabot.cartago.bridge.SourceCompiler;
import jacabot.experiments.link.LinkRegistry;
import jacabot.robot.Experiment;
import jacabot.robot.link.LinkSecret;
import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.regex.Pattern;
import javax.net.ssl.SSLContext;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jacabot run FILE}: runs a Jason project (.mas2j) or a single agent (.asl). */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = {"Runs a Jason project (.mas2j) or one agent (.asl, named after the file) until .stopMAS.",
                "Console lines are printed as Jason prints them: [agent] text.",
                "With a robot's middleware (agents/src/main/asl/*.mas2j) it listens for `jacabot controller`."})
final class RunCommand implements Callable<Integer> {
    /** Syntax errors say where they are and that they are errors: no second "error: " before them. */
    private static final Pattern LOCATED = Pattern.compile("[^\\n]*:\\d+:\\d+: error: ");

    /** The belief the robot agents read their middleware's port from (their .asl holds the default). */
    static final String PORT_BELIEF = "middlewarePort";

    @Parameters(index = "0", paramLabel = "FILE", description = "a .mas2j project, a JaCaMo .jcm project or an .asl agent")
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

    @Option(names = "--port", paramLabel = "PORT",
            description = "the middleware's port: replaces the agents' " + PORT_BELIEF + "(P) belief (their default 4444)")
    private Integer port;

    @Option(names = "--secret-file", paramLabel = "FILE",
            description = "the link secret shared with `jacabot controller` (default ~/.jacabot/link-secret, made 0600 if absent)")
    private Path secretFile;

    @Option(names = "--tls-store", paramLabel = "FILE",
            description = "the middleware takes the controller over TLS, with the key of this store (PKCS12 or JKS, made with keytool); "
                    + "it listens on --tls-address at the middleware's port")
    private Path tlsStore;

    @Option(names = "--tls-password-file", paramLabel = "FILE", description = "the --tls-store's password, on the file's first line")
    private Path tlsPasswordFile;

    @Option(names = "--tls-address", paramLabel = "HOST",
            description = "with --tls-store: the address to listen on, e.g. this machine's address on the lab network (default ${DEFAULT-VALUE})")
    private String tlsAddress = "127.0.0.1";

    @Mixin
    private InspectorOptions inspectorOptions = new InspectorOptions();

    @Mixin
    private VerbosityOptions verbosity = new VerbosityOptions();

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        var log = verbosity.console(spec);
        var out = log.agentsVerbatim(); // as Jason prints it: a Jason program's output is compared line for line
        if (port != null && (port < 1 || port > 65535)) {
            throw new UserError("--port must be in 1..65535, got " + port);
        }
        if (secretFile != null) {
            System.setProperty(LinkSecret.FILE_PROPERTY, secretFile.toString());
            LinkSecret.resetUserDefault();
        }
        LocalMAS mas;
        try {
            // the project's artifacts: classpath: entries, --classpath, Java sources beside the .mas2j
            var entries = new ArrayList<Path>();
            classpath.forEach(c -> Arrays.stream(c.split(File.pathSeparator)).filter(e -> !e.isEmpty())
                    .map(Path::of).forEach(entries::add));
            file = Installation.locate(file);
            var classes = ProjectClasses.prepare(file.toString().endsWith(".asl") ? null : file, entries);
            classes.classpath().warnings().forEach(err::println);
            Thread.currentThread().setContextClassLoader(classes.loader());
            var launcher = new MasLauncher(out, seed, stepping);
            mas = launcher.load(file);
        } catch (ProjectClasspath.Problem e) {
            throw UserError.located(e.getMessage());
        } catch (SourceCompiler.CompileError e) {
            throw UserError.located(String.join(System.lineSeparator(), e.lines())); // file:line: message, one per error
        } catch (MasLauncher.UserError e) {
            if (LOCATED.matcher(e.getMessage()).lookingAt()) {
                err.println(e.getMessage()); // file:line:col: error: message, one line per error
                return 2;
            }
            throw new UserError(e.getMessage());
        }
        if (file.toString().endsWith(".mas2j")) {
            projectWarnings(file).forEach(log::warn);
        }
        int listen = port != null ? port : declaredPort(mas);
        if (tlsStore != null && listen <= 0) {
            throw new UserError("--tls-store: no agent of " + file + " has a robot middleware (" + PORT_BELIEF + "(P) belief)");
        }
        SSLContext tls = tlsStore != null ? TlsOptions.context(tlsStore, tlsPasswordFile) : null;
        if (tls == null && tlsPasswordFile != null) {
            throw new UserError("--tls-password-file goes with --tls-store FILE");
        }
        int middlewarePort = tls != null ? freeLoopbackPort() : listen; // behind the TLS relay
        if (port != null || tls != null) {
            for (String name : mas.agentNames()) {
                setPort(mas.agent(name), middlewarePort);
            }
        }
        TlsRelay relay = null;
        if (tls != null) {
            try {
                relay = TlsRelay.start(tls, InetAddress.getByName(tlsAddress), listen, middlewarePort,
                        line -> err.println("[middleware] " + line));
            } catch (IOException e) {
                throw new IllegalStateException("cannot listen with TLS on " + tlsAddress + ":" + listen + " (" + e.getMessage()
                        + "); choose another with --port or --tls-address");
            }
            err.println("[middleware] TLS on " + tlsAddress + ":" + listen + ", relayed to the middleware on loopback");
        }
        if (listen > 0) {
            if (tls == null) {
                checkFree(listen);
            }
            try {
                LinkSecret.userDefault(); // a secret file that cannot be read is told now, in one line
            } catch (UncheckedIOException e) {
                throw new UserError(e.getMessage() + " (or pass --secret-file FILE)");
            }
            // the middleware waits for the robot controller: a run that seems to hang says what it waits for
            String stem = file.getFileName().toString().replaceFirst("\\.(mas2j|asl)$", "");
            String worldFile = Experiment.parse(stem).map(e -> e.worldFile()).orElse("FILE");
            log.info("Waiting for the robot controller on " + (tls != null ? tlsAddress : "127.0.0.1") + ":" + listen
                    + "; start it in another terminal: jacabot controller --world " + worldFile
                    + (port != null ? " --port " + listen : "") + (tls != null ? " --host " + tlsAddress + " --tls-store ..." : ""));
        }
        // the middleware's heartbeats (the controller's fail-safe) follow the agents' reasoning
        var watch = new AgentWatch(mas, RealTimeRun.STALL_MS);
        // off by default: console programs end in moments; --inspector shows their minds
        var results = ConsoleLog.lines(log::result);
        var inspector = inspectorOptions.start(false, "jacabot run " + file, results, log::warn);
        AutoCloseable sampling = () -> {
        };
        if (inspector != null) {
            var watches = new ArrayList<MindWatch>();
            for (String name : mas.agentNames()) {
                watches.add(MindWatch.attach(inspector, mas.agent(name), null));
            }
            sampling = MindWatch.sampleEvery(watches, 200);
        }
        LinkRegistry.setDefaultLiveness(watch); // the agents make their middleware, and so its link, as they run
        LinkRegistry.setDefaultQuiescence(watch::idle); // a lockstep controller's step waits for the agents' answer
        try {
            if (stepping) {
                mas.runStepping();
            } else {
                mas.runThreads();
            }
        } finally {
            // the defaults are the process's: links opened after this run (the next in-process
            // command, a test) must not ask agents that have stopped
            LinkRegistry.setDefaultLiveness(() -> true);
            LinkRegistry.setDefaultQuiescence(() -> true);
        }
        sampling.close();
        if (relay != null) {
            relay.close();
        }
        if (inspector != null) {
            inspectorOptions.linger(inspector, results);
            inspector.close();
        }
        log.flush(); // the counts of the last folded lines
        if (stats) {
            long cycles = 0;
            for (String name : mas.agentNames()) {
                cycles += mas.agent(name).cycles();
            }
            err.println("cycles " + cycles);
        }
        return 0;
    }

    /** {@return warnings when a robot project's agents make another experiment's middleware than it is named for} */
    static List<String> projectWarnings(Path mas2j) {
        try {
            String text = Files.readString(mas2j);
            var name = Pattern.compile("\\bMAS\\s+(\\w+)").matcher(text);
            if (!name.find()) {
                return List.of();
            }
            var made = new ArrayList<String>();
            var asl = Pattern.compile("([\\w./-]+\\.asl)\\b").matcher(text);
            while (asl.find()) {
                Path agent = mas2j.toAbsolutePath().getParent().resolve(asl.group(1));
                if (Files.isRegularFile(agent)) {
                    made.addAll(ExperimentMatch.middlewaresMadeBy(Files.readString(agent)));
                }
            }
            return ExperimentMatch.checkProject(name.group(1), mas2j.toString(), made);
        } catch (IOException | RuntimeException e) {
            return List.of(); // the launcher has loaded it already; a check that cannot read it stays silent
        }
    }

    /** {@return the port in an agent's {@value #PORT_BELIEF} belief, or 0 when none declares one} */
    private static int declaredPort(LocalMAS mas) {
        for (String name : mas.agentNames()) {
            for (Literal b : mas.agent(name).beliefBase().beliefs()) {
                if (isPortBelief(b) && b.arg(0) instanceof NumberTerm n) {
                    return (int) n.value();
                }
            }
        }
        return 0;
    }

    private static boolean isPortBelief(Literal b) {
        return b.arity() == 1 && b.toString().startsWith(PORT_BELIEF + "(");
    }

    /** The launcher's port wins over the program's default: the old belief goes, the new one comes. */
    static void setPort(Agent agent, int port) {
        for (Literal b : agent.beliefBase().beliefs()) {
            if (isPortBelief(b)) {
                agent.beliefBase().removeEntry(b);
            }
        }
        agent.addBelief(Literal.of(PORT_BELIEF, new NumberTerm(port)).addAnnot(Literal.SOURCE_SELF), false);
    }

    private static int freeLoopbackPort() throws IOException {
        try (ServerSocket probe = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return probe.getLocalPort();
        }
    }

    /** A port in use is a one-line error with what to do, not a run that ends quietly. */
    private static void checkFree(int port) {
        try (ServerSocket probe = new ServerSocket()) {
            probe.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        } catch (IOException e) {
            throw new IllegalStateException("port " + port + " is in use (another jacabot run?); "
                    + "stop it or choose another with --port (and the same --port for `jacabot controller`)");
        }
    }
}
