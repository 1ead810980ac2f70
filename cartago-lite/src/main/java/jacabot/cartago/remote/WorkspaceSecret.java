package jacabot.cartago.remote;

import jacabot.secret.SecretFile;
import java.io.IOException;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.SecureRandom;
import java.util.HexFormat;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The key a workspace node and the agents that join it from other processes share, to prove to
 * each other who they are ({@link RemoteHandshake}); it never travels. By default it is the file
 * {@code ~/.jacabot/workspace-secret} (or {@value #FILE_PROPERTY}), made with mode 0600 by the first
 * process that needs it, so the processes of one user on one machine agree without setup.
 */
public final class WorkspaceSecret {
    public static final String FILE_PROPERTY = "jacabot.workspaceSecretFile";
    private static final SecureRandom RANDOM = new SecureRandom();
    /** The secret's name in messages. */
    private static final String NAME = "workspace secret";
    private final byte[] key;

    private WorkspaceSecret(byte[] key) {
        if (key.length < 16) {
            throw new IllegalArgumentException("a workspace secret needs at least 16 bytes");
        }
        this.key = key.clone();
    }

    /** {@return a fresh random secret (both ends in one process, tests)} */
    public static WorkspaceSecret random() {
        return new WorkspaceSecret(nonce(32));
    }

    static byte[] nonce(int n) {
        byte[] b = new byte[n];
        RANDOM.nextBytes(b);
        return b;
    }

    /** {@return the file {@value #FILE_PROPERTY} names, else {@code ~/.jacabot/workspace-secret}} */
    public static Path defaultFile() {
        String p = System.getProperty(FILE_PROPERTY);
        return p != null ? Path.of(p) : Path.of(System.getProperty("user.home"), ".jacabot", "workspace-secret");
    }

    /**
     * {@return the secret in {@code file}, which is made (0600) with a fresh one when absent}; two
     * processes starting together end with the same one: the file appears whole or not at all
     * ({@link SecretFile}), and the one that loses reads the other's.
     *
     * @throws IOException when it cannot be read or made, holds no secret, or others may read it
     */
    public static WorkspaceSecret loadOrCreate(Path file) throws IOException {
        String hex = SecretFile.loadOrCreate(file, NAME, HexFormat.of().formatHex(nonce(32)));
        try {
            return new WorkspaceSecret(HexFormat.of().parseHex(hex));
        } catch (IllegalArgumentException e) {
            throw new IOException(file + ": not a " + NAME + " (" + e.getMessage() + ")");
        }
    }

    /** {@return HMAC-SHA256 of the parts, in order} */
    byte[] mac(byte[]... parts) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
            for (byte[] p : parts) {
                mac.update(p);
            }
            return mac.doFinal();
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is part of every JDK", e);
        }
    }

    @Override
    public String toString() {
        return "WorkspaceSecret[" + key.length + " bytes]";
    }
}
