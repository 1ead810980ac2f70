package jacabot.cartago.remote;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;

/**
 * Mutual challenge-response before any frame, as the robot link's: neither end takes requests
 * from, or gives events to, a process that does not hold the {@link WorkspaceSecret}.
 *
 * <pre>
 * client → node    "JCWS", version, nonceC (32 bytes)
 * node   → client  version, nonceN, HMAC(K, "node" | nonceC | nonceN)
 * client → node    HMAC(K, "client" | nonceN | nonceC)         (after checking the node's)
 * node   → client  1                                            (session open)
 * </pre>
 */
final class RemoteHandshake {
    static final int VERSION = 1;
    private static final byte[] MAGIC = "JCWS".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] NODE = "jacabot workspace node".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] CLIENT = "jacabot workspace client".getBytes(StandardCharsets.US_ASCII);
    private static final int NONCE = 32;

    private RemoteHandshake() {
    }

    static void asClient(DataInputStream in, DataOutputStream out, WorkspaceSecret secret) throws IOException {
        byte[] nonceC = WorkspaceSecret.nonce(NONCE);
        out.write(MAGIC);
        out.writeInt(VERSION);
        out.write(nonceC);
        out.flush();
        int version = in.readInt();
        if (version != VERSION) {
            throw new IOException("the node speaks version " + version + " of the workspace protocol, we speak " + VERSION);
        }
        byte[] nonceN = read(in, NONCE);
        if (!MessageDigest.isEqual(read(in, 32), secret.mac(NODE, nonceC, nonceN))) {
            throw new IOException("the node cannot prove the workspace secret (another secret file, or not a node)");
        }
        out.write(secret.mac(CLIENT, nonceN, nonceC));
        out.flush();
        if (in.read() != 1) {
            throw new IOException("the node refused our proof of the workspace secret (another secret file?)");
        }
    }

    static void asNode(DataInputStream in, DataOutputStream out, WorkspaceSecret secret) throws IOException {
        if (!MessageDigest.isEqual(read(in, MAGIC.length), MAGIC)) {
            throw new IOException("not a workspace client");
        }
        int version = in.readInt();
        out.writeInt(VERSION);
        if (version != VERSION) {
            out.flush();
            throw new IOException("a client of protocol version " + version + ", we speak " + VERSION);
        }
        byte[] nonceC = read(in, NONCE);
        byte[] nonceN = WorkspaceSecret.nonce(NONCE);
        out.write(nonceN);
        out.write(secret.mac(NODE, nonceC, nonceN));
        out.flush();
        if (!MessageDigest.isEqual(read(in, 32), secret.mac(CLIENT, nonceN, nonceC))) {
            throw new IOException("the client could not prove the workspace secret");
        }
        out.write(1);
        out.flush();
    }

    private static byte[] read(DataInputStream in, int n) throws IOException {
        byte[] b = new byte[n];
        in.readFully(b);
        return b;
    }
}
