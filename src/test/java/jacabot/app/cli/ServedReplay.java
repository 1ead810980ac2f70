package jacabot.app.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URI;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code jacabot replay RUN --headless --inspector} (or a live {@code jacabot experiment ... --inspector})
 * run in-process through the launcher's own command line, on a thread of its own: the address it
 * prints is read from its output, and {@link #close} quits it as a user would (an interrupt stands
 * for Ctrl-C) and waits for it to end.
 */
public final class ServedReplay implements AutoCloseable {
    private static final Pattern SERVED = Pattern.compile("is served at (http://\\S+) ;");
    private static final Pattern LIVE = Pattern.compile("Mind inspector: (http://\\S+)");

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();
    private final AtomicInteger exit = new AtomicInteger(-1);
    private final Thread thread;
    private final URI address;

    private ServedReplay(Pattern served, String... args) throws InterruptedException {
        var cl = JacabotCommand.commandLine(args);
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        thread = new Thread(() -> exit.set(cl.execute(args)), "replay-command");
        thread.setDaemon(true);
        thread.start();
        URI found = null;
        for (long end = System.nanoTime() + 60_000_000_000L; found == null && System.nanoTime() < end && thread.isAlive(); ) {
            Matcher m = served.matcher(out.toString());
            if (m.find()) {
                found = URI.create(m.group(1));
            } else {
                Thread.sleep(50);
            }
        }
        if (found == null) {
            close();
            throw new AssertionError("the command served nothing (exit " + exit.get() + "):\n" + out + err);
        }
        address = found;
    }

    /** Starts {@code jacabot replay RUN --headless --inspector [more]} and waits for the address it prints. */
    public static ServedReplay start(Path run, String... more) throws InterruptedException {
        String[] args = new String[4 + more.length];
        args[0] = "replay";
        args[1] = run.toString();
        args[2] = "--headless";
        args[3] = "--inspector";
        System.arraycopy(more, 0, args, 4, more.length);
        return new ServedReplay(SERVED, args);
    }

    /** Starts {@code jacabot experiment ARGS} (with {@code --inspector} among them) and waits for the address it prints. */
    public static ServedReplay experiment(String... args) throws InterruptedException {
        String[] all = new String[1 + args.length];
        all[0] = "experiment";
        System.arraycopy(args, 0, all, 1, args.length);
        return new ServedReplay(LIVE, all);
    }

    /** Records a short real run: {@code jacabot experiment NAME --headless --duration D --seed S --out OUT}. */
    public static void record(String experiment, String duration, int seed, Path out) {
        String[] r = CliRun.run("experiment", experiment, "--headless", "--quiet", "--duration", duration,
                "--seed", String.valueOf(seed), "--out", out.toString());
        if (!r[0].equals("0")) {
            throw new AssertionError("the run to replay failed (exit " + r[0] + "):\n" + r[1] + r[2]);
        }
    }

    /** {@return the address the command printed, with its token} */
    public URI address() {
        return address;
    }

    /** {@return what the command printed so far} */
    public String output() {
        return out + err.toString();
    }

    /** {@return the exit code, -1 while it runs} */
    public int exitCode() {
        return exit.get();
    }

    /** Quits the command (an interrupt, as Ctrl-C) and waits for it to end. */
    @Override
    public void close() throws InterruptedException {
        thread.interrupt();
        thread.join(20_000);
    }
}
