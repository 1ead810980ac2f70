package jacabot.cartago.examples;

import jacabot.cartago.Artifact;
import jacabot.cartago.IBlockingCmd;
import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;

/**
 * A boundary artifact in the style of the thesis' middleware artifact: it listens on a loopback
 * port and reads lines through await(IBlockingCmd), so that its other operations keep running.
 */
public class LineReader extends Artifact {
    private ServerSocket server;
    private Socket socket;

    void init() throws IOException {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        defineObsProperty("port", server.getLocalPort());
        defineObsProperty("last", "");
    }

    @OPERATION
    void serve() {
        execInternalOp("readLoop");
    }

    @OPERATION
    void ping(OpFeedbackParam<String> reply) {
        reply.set("pong");
    }

    @INTERNAL_OPERATION
    void readLoop() {
        Accept accept = new Accept();
        await(accept);
        socket = accept.socket;
        signal("connected");
        ReadLine read = new ReadLine(accept.in);
        while (true) {
            await(read);
            if (read.line == null) {
                break;
            }
            getObsProperty("last").updateValue(read.line);
            signal("received", read.line);
        }
        signal("closed");
    }

    @Override
    protected void dispose() {
        try {
            server.close();
            if (socket != null) {
                socket.close();
            }
        } catch (IOException e) {
            log("closing: " + e);
        }
    }

    private final class Accept implements IBlockingCmd {
        private Socket socket;
        private BufferedReader in;

        @Override
        public void exec() {
            try {
                socket = server.accept();
                in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }

    private static final class ReadLine implements IBlockingCmd {
        private final BufferedReader in;
        private String line;

        ReadLine(BufferedReader in) {
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
}
