package jacabot.cartago.remote;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
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
     * {@return the secret in {@code file}, which is made (0600) with a fresh one when absent}; two
     * processes starting together end with the same one: the file appears whole or not at all
     * ({@link #publish}), and the one that loses reads the other's.
     *
     * @throws IOException when it cannot be read or made, holds no secret, or others may read it
     */
    public static WorkspaceSecret loadOrCreate(Path file) throws IOException {
        if (!Files.exists(file)) {
            Path dir = file.toAbsolutePath().getParent();
            Files.createDirectories(dir);
            byte[] fresh = nonce(32);
            if (publish(file, HexFormat.of().formatHex(fresh) + "\n")) {
                return new WorkspaceSecret(fresh);
            }
            // another process published its secret first: read that one
        }
        return load(file);
    }

    /**
     * Writes {@code text} to a temporary file beside {@code file} (0600 from the start) and gives it
     * {@code file}'s name in one step unless the name exists by then; {@return whether it was published}.
     * A hard link, as {@code LinkSecret} publishes its file: a rename would replace a secret published
     * meanwhile; without hard links, an atomic move after a last look.
     */
    private static boolean publish(Path file, String text) throws IOException {
        Path dir = file.toAbsolutePath().getParent();
        Path tmp = Files.getFileStore(dir).supportsFileAttributeView(PosixFileAttributeView.class)
                ? Files.createTempFile(dir, "." + file.getFileName(), ".tmp", PosixFilePermissions.asFileAttribute(
                        Set.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE)))
                : Files.createTempFile(dir, "." + file.getFileName(), ".tmp");
        try {
            Files.writeString(tmp, text, StandardCharsets.US_ASCII);
            try {
                Files.createLink(file, tmp);
            } catch (UnsupportedOperationException | FileSystemException noLinks) {
                if (noLinks instanceof FileAlreadyExistsException || Files.exists(file)) {
                    return false;
                }
                Files.move(tmp, file, StandardCopyOption.ATOMIC_MOVE);
            }
            return true;
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    private static WorkspaceSecret load(Path file) throws IOException {
        if (Files.getFileStore(file).supportsFileAttributeView(PosixFileAttributeView.class)) {
            Set<PosixFilePermission> perms = Files.getPosixFilePermissions(file);
            if (perms.contains(PosixFilePermission.GROUP_READ) || perms.contains(PosixFilePermission.OTHERS_READ)) {
                throw new IOException("the workspace secret " + file + " may be read by other users; run: chmod 600 " + file);
            }
        }
        String text = Files.readString(file, StandardCharsets.US_ASCII).trim();
        try {
            return new WorkspaceSecret(HexFormat.of().parseHex(text));
        } catch (IllegalArgumentException e) {
            throw new IOException(file + ": not a workspace secret (" + e.getMessage() + ")");
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
