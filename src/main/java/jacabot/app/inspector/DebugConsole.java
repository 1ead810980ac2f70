package jacabot.app.inspector;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * Breakpoints from the command line ({@code --break SPEC}), for a user without a browser: at each
 * halt it prints the mind and reads commands from the console until the run goes on. The end of
 * the input lets the run go without further halts (a batch job never hangs).
 */
public final class DebugConsole {
    static final String HELP = "  Enter or c: continue   s: one control step   n: one reasoning cycle   b SPEC: add a breakpoint   "
            + "d SPEC: delete one   l: list   p: print the mind   q: no more halts";

    private DebugConsole() {
    }

    /**
     * {@return a debugger with these breakpoints, driven from {@code in}}
     *
     * @throws IllegalArgumentException naming a breakpoint that does not parse
     */
    public static Debugger start(List<String> breaks, InputStream in, PrintStream out) {
        var d = new Debugger();
        breaks.forEach(d::add);
        d.onHalt(h -> {
            out.printf("%nHalted at t=%.2f s: %s%n", h.timeMs() / 1000.0, h.reason());
            MindText.print(h.mind(), out);
            out.println(HELP);
            out.print("debug> ");
            out.flush();
        });
        Thread reader = new Thread(() -> read(d, in, out), "debug-console");
        reader.setDaemon(true);
        reader.start();
        return d;
    }

    private static void read(Debugger d, InputStream in, PrintStream out) {
        var lines = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
        try {
            while (true) {
                d.awaitHalt(); // a command is read at a halt only: typed (or piped) ahead, it waits for one
                String line = lines.readLine();
                if (line == null) {
                    break;
                }
                command(d, line.trim(), out);
            }
        } catch (IOException | InterruptedException e) {
            // the console went away: as at its end
        }
        d.detach();
    }

    static void command(Debugger d, String c, PrintStream out) {
        Debugger.Halt h = d.halted();
        try {
            if (c.isEmpty() || c.equals("c")) {
                d.resume();
            } else if (c.equals("s")) {
                d.step();
            } else if (c.equals("n")) {
                d.stepCycle();
            } else if (c.startsWith("b ")) {
                out.println("  breakpoint " + d.add(c.substring(2)).text());
            } else if (c.startsWith("d ")) {
                out.println(d.remove(c.substring(2)) ? "  deleted" : "  no breakpoint " + c.substring(2));
            } else if (c.equals("l")) {
                if (d.breakpoints().isEmpty()) {
                    out.println("  no breakpoints (a time one is gone once reached)");
                }
                d.breakpoints().forEach(b -> out.println("  " + b.text()));
            } else if (c.equals("p") && h != null) {
                MindText.print(h.mind(), out);
            } else if (c.equals("q")) {
                d.detach();
            } else {
                out.println("  ? " + c + "\n" + HELP);
            }
        } catch (IllegalArgumentException e) {
            out.println("  " + e.getMessage());
        }
        if (d.halted() != null) {
            out.print("debug> ");
            out.flush();
        }
    }
}
