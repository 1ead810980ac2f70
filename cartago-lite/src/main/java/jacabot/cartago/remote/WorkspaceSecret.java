package jacabot.cartago.remote;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.Set;
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
     * {@return the secret in {@code file}, which is made (0600) with a fresh one when absent}
     *
     * @throws IOException when it cannot be read or made, holds no secret, or others may read it
     */
    public static WorkspaceSecret loadOrCreate(Path file) throws IOException {
        if (!Files.exists(file)) {
            Path dir = file.toAbsolutePath().getParent();
            Files.createDirectories(dir);
            boolean posix = Files.getFileStore(dir).supportsFileAttributeView(PosixFileAttributeView.class);
            try {
                if (posix) {
                    Files.createFile(file, PosixFilePermissions.asFileAttribute(
                            Set.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE)));
                } else {
                    Files.createFile(file);
                }
                byte[] fresh = nonce(32);
                Files.writeString(file, HexFormat.of().formatHex(fresh) + "\n", StandardCharsets.US_ASCII);
                return new WorkspaceSecret(fresh);
            } catch (FileAlreadyExistsException madeMeanwhile) {
                // another process made it: read it below
            }
        }
        return load(file);
    }

    private static WorkspaceSecret load(Path file) throws IOException {
        if (Files.getFileStore(file).supportsFileAttributeView(PosixFileAttributeView.class)) {
            Set<PosixFilePermission> perms = Files.getPosixFilePermissions(file);
            if (perms.contains(PosixFilePermission.GROUP_READ) || perms.contains(PosixFilePermission.OTHERS_READ)) {
                throw new IOException("the workspace secret " + file + " may be read by other users; run: chmod 600 " + file);
            }
        }
        for (int attempt = 0; ; attempt++) {
            String text = Files.readString(file, StandardCharsets.US_ASCII).trim();
            if (!text.isEmpty() || attempt == 20) {
                try {
                    return new WorkspaceSecret(HexFormat.of().parseHex(text));
                } catch (IllegalArgumentException e) {
                    throw new IOException(file + ": not a workspace secret (" + e.getMessage() + ")");
                }
            }
            try {
                Thread.sleep(25);   // being written by the process that made it
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while reading " + file);
            }
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
