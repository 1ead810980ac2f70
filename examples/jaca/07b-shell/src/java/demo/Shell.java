package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.IBlockingCmd;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/** Runs commands with sh -c. Reading their output blocks, so it happens in await: the artifact stays free. */
public class Shell extends Artifact {
    /** Reads one line of a process's output (null at its end). */
    private static final class NextLine implements IBlockingCmd {
        private final BufferedReader in;
        String line;

        NextLine(BufferedReader in) {
            this.in = in;
        }

        @Override
        public void exec() {
            try {
                line = in.readLine();
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }

    private static Process start(String command) {
        try {
            return new ProcessBuilder("sh", "-c", command).redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static BufferedReader output(Process p) {
        return new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
    }

    /** The first line the command prints. */
    @OPERATION
    void firstLine(String command, OpFeedbackParam<String> line) {
        Process p = start(command);
        NextLine next = new NextLine(output(p));
        await(next);
        p.destroy();
        if (next.line == null) {
            failed(command + " printed nothing", "no_output", command);
        }
        line.set(next.line);
    }

    /** Signals line(N, Text) for each line the command prints; fails if it exits with an error. */
    @OPERATION
    void stream(String command) throws InterruptedException {
        Process p = start(command);
        BufferedReader out = output(p);
        int n = 0;
        while (true) {
            NextLine next = new NextLine(out);
            await(next);
            if (next.line == null) {
                break;
            }
            signal("line", ++n, next.line);
        }
        int code = p.waitFor();
        if (code != 0) {
            failed(command + " exited with " + code, "exit_code", code);
        }
    }
}
