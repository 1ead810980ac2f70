package jacabot.experiments.link;

import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;

/**
 * A second local process without the secret, trying to take the robot over: it greets the
 * middleware as a controller would, with a key of its own, again and again (the audit's attack:
 * 146 takeovers in 15 s before sessions were authenticated). Prints {@code attempts N takeovers M}.
 *
 * <p>{@code java -cp ... jacabot.experiments.link.Intruder PORT ATTEMPTS SECONDS}
 */
public final class Intruder {
    private Intruder() {
    }

    public static void main(String[] args) throws Exception {
        int port = Integer.parseInt(args[0]);
        int attempts = Integer.parseInt(args[1]);
        long end = System.nanoTime() + Long.parseLong(args[2]) * 1_000_000_000L;
        LinkSecret mine = LinkSecret.random();
        int made = 0, takeovers = 0;
        var hello = new Protocol.Hello(Protocol.VERSION, "khepera", "navigation", 40, false);
        while (made < attempts && System.nanoTime() < end) {
            made++;
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
                s.setSoTimeout(2000);
                var out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                if (made % 2 == 0) {
                    // the full exchange with our own key: the middleware's proof fails our check
                    Handshake.asController(new DataInputStream(s.getInputStream()), out, hello, mine);
                    takeovers++;
                } else {
                    // ignore its proof and answer with a forged one, as an intruder would
                    out.write(hello.bytes());
                    out.write(new byte[Handshake.NONCE_BYTES]);
                    out.flush();
                    var in = new DataInputStream(s.getInputStream());
                    Protocol.Welcome.read(in);
                    in.readFully(new byte[Handshake.NONCE_BYTES + Handshake.MAC_BYTES]);
                    out.write(new byte[Handshake.MAC_BYTES]);
                    out.flush();
                    if (in.read() == 1) {
                        takeovers++; // the session opened for us
                    }
                }
            } catch (IOException e) {
                // refused: proof wrong, rate-limited, or closed unheard
            }
        }
        System.out.println("attempts " + made + " takeovers " + takeovers);
    }
}
