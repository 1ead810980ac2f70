package jacabot.robot.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;

/**
 * Mutual challenge-response after the greeting, so that neither end takes orders from a process
 * that does not hold the {@link LinkSecret} (which never travels):
 *
 * <pre>
 * controller → middleware  Hello, nonceC (32 random bytes)
 * middleware → controller  Welcome, nonceM, HMAC(K, "middleware" | nonceC | nonceM | Hello)
 * controller → middleware  HMAC(K, "controller" | nonceM | nonceC | Hello)     (after checking the above)
 * middleware → controller  1                                                     (session open)
 * </pre>
 *
 * Fresh nonces on both sides make an old exchange worthless; the labels make one side's proof
 * useless as the other's; the Hello is covered, so the declared robot cannot be altered on the way.
 * Proofs are compared in constant time. A refused version ends the exchange after the Welcome.
 */
public final class Handshake {
    public static final int NONCE_BYTES = 32;
    public static final int MAC_BYTES = 32;
    private static final byte[] MIDDLEWARE = "jacabot middleware".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] CONTROLLER = "jacabot controller".getBytes(StandardCharsets.US_ASCII);
    private static final int SESSION_OPEN = 1;

    private Handshake() {
    }

    /**
     * The controller's side: greets, checks the middleware's proof, proves itself.
     *
     * @throws ProtocolException      when the middleware refuses (e.g. another version) or is not one
     * @throws AuthenticationException when the middleware cannot prove the secret, or refuses ours
     */
    public static Protocol.Welcome asController(DataInputStream in, DataOutputStream out, Protocol.Hello hello,
            LinkSecret secret) throws IOException {
        byte[] helloBytes = hello.bytes();
        byte[] nonceC = LinkSecret.nonce(NONCE_BYTES);
        out.write(helloBytes);
        out.write(nonceC);
        out.flush();
        Protocol.Welcome welcome = Protocol.Welcome.read(in);
        if (!welcome.accepted()) {
            throw new ProtocolException("the middleware refused the connection: " + welcome.message());
        }
        byte[] nonceM = readFully(in, NONCE_BYTES, "middleware");
        byte[] proof = readFully(in, MAC_BYTES, "middleware");
        if (!MessageDigest.isEqual(proof, secret.mac(MIDDLEWARE, nonceC, nonceM, helloBytes))) {
            throw new AuthenticationException("the middleware cannot prove the link secret (a stranger on the port, "
                    + "or another secret file): not connecting");
        }
        out.write(secret.mac(CONTROLLER, nonceM, nonceC, helloBytes));
        out.flush();
        int open;
        try {
            open = in.read();
        } catch (IOException e) {
            open = -1;
        }
        if (open != SESSION_OPEN) {
            throw new AuthenticationException("the middleware refused our proof of the link secret "
                    + "(another secret file?)");
        }
        return welcome;
    }

    /**
     * The middleware's side: reads the greeting, proves itself, checks the controller's proof.
     *
     * @throws ProtocolException      for garbage or another version (refused with a Welcome saying why)
     * @throws AuthenticationException when the controller's proof is wrong
     */
    public static Protocol.Hello asMiddleware(DataInputStream in, DataOutputStream out, LinkSecret secret)
            throws IOException {
        Protocol.Hello hello = Protocol.Hello.read(in);
        String mismatch = Protocol.versionMismatch(hello.version(), Protocol.VERSION);
        if (mismatch != null) {
            new Protocol.Welcome(Protocol.VERSION, false, mismatch).write(out);
            throw new ProtocolException(mismatch);
        }
        byte[] helloBytes = hello.bytes();
        byte[] nonceC = readFully(in, NONCE_BYTES, "controller");
        byte[] nonceM = LinkSecret.nonce(NONCE_BYTES);
        new Protocol.Welcome(Protocol.VERSION, true, "welcome").writeUnflushed(out);
        out.write(nonceM);
        out.write(secret.mac(MIDDLEWARE, nonceC, nonceM, helloBytes));
        out.flush();
        byte[] proof = readFully(in, MAC_BYTES, "controller");
        if (!MessageDigest.isEqual(proof, secret.mac(CONTROLLER, nonceM, nonceC, helloBytes))) {
            throw new AuthenticationException("the controller could not prove the link secret");
        }
        out.write(SESSION_OPEN);
        out.flush();
        return hello;
    }

    private static byte[] readFully(DataInputStream in, int n, String peer) throws IOException {
        byte[] b = new byte[n];
        try {
            in.readFully(b);
        } catch (EOFException e) {
            throw new ProtocolException("truncated handshake from the " + peer);
        }
        return b;
    }
}
