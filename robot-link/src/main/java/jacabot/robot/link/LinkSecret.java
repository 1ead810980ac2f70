package jacabot.robot.link;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.InvalidKeyException;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.EnumSet;
import java.util.HexFormat;
import java.util.Set;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The key both ends of the link share to prove to each other who they are ({@link Handshake}). It
 * never travels on the wire. An experiment run in one process makes a fresh one ({@link #random()});
 * the two-process set-up reads it from a file only its owner may read ({@link #loadOrCreate(Path)},
 * by default {@code ~/.jacabot/link-secret}, made with mode 0600 when absent).
 */
public final class LinkSecret {
    /** 256-bit keys, as HMAC-SHA256 wants. */
    public static final int BYTES = 32;
    /** Overrides the default file (the launchers' {@code --secret-file}). */
    public static final String FILE_PROPERTY = "jacabot.secretFile";
    private static final SecureRandom RANDOM = new SecureRandom();
    private static volatile LinkSecret userDefault;

    private final byte[] key;

    private LinkSecret(byte[] key) {
        if (key.length < 16) {
            throw new IllegalArgumentException("a link secret needs at least 16 bytes, got " + key.length);
        }
        this.key = key.clone();
    }

    /** {@return a fresh secret from {@link SecureRandom}} */
    public static LinkSecret random() {
        byte[] k = new byte[BYTES];
        RANDOM.nextBytes(k);
        return new LinkSecret(k);
    }

    /** {@return a secret from its hex form (at least 32 hex digits)} */
    public static LinkSecret fromHex(String hex) {
        try {
            return new LinkSecret(HexFormat.of().parseHex(hex.trim()));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("a link secret is at least 32 hex digits: " + e.getMessage());
        }
    }

    /** {@return {@code size} fresh random bytes (handshake nonces)} */
    static byte[] nonce(int size) {
        byte[] n = new byte[size];
        RANDOM.nextBytes(n);
        return n;
    }

    /** {@return the default file: {@value #FILE_PROPERTY} if set, else {@code ~/.jacabot/link-secret}} */
    public static Path defaultFile() {
        String p = System.getProperty(FILE_PROPERTY);
        return p != null ? Path.of(p) : Path.of(System.getProperty("user.home"), ".jacabot", "link-secret");
    }

    /**
     * {@return the secret of the default file, made on first use}
     *
     * @throws UncheckedIOException when the file cannot be read or made, or others may read it
     */
    public static LinkSecret userDefault() {
        LinkSecret s = userDefault;
        if (s == null) {
            synchronized (LinkSecret.class) {
                if (userDefault == null) {
                    try {
                        userDefault = loadOrCreate(defaultFile());
                    } catch (IOException e) {
                        throw new UncheckedIOException(e.getMessage(), e);
                    }
                }
                s = userDefault;
            }
        }
        return s;
    }

    /** Forgets the cached default secret (after {@value #FILE_PROPERTY} changed). */
    public static void resetUserDefault() {
        userDefault = null;
    }

    /**
     * Makes {@code secret} the default of this process instead of the file's: a launcher that runs
     * both ends in one process (an experiment with the viewer) uses a fresh one per run.
     */
    public static void useInThisProcess(LinkSecret secret) {
        userDefault = secret;
    }

    /**
     * Reads the secret in {@code file}, or makes the file (mode 0600, its directory 0700) with a fresh
     * secret when it does not exist. Two processes starting together end with the same secret: the
     * file appears whole or not at all ({@link #publish}), and the one that loses reads the other's.
     *
     * @throws IOException when it cannot be read or made, holds no secret, or group or others may read it
     */
    public static LinkSecret loadOrCreate(Path file) throws IOException {
        if (!Files.exists(file)) {
            LinkSecret fresh = random();
            Path dir = file.toAbsolutePath().getParent();
            boolean posix = Files.getFileStore(Files.exists(dir) ? dir : dir.getRoot())
                    .supportsFileAttributeView(PosixFileAttributeView.class);
            if (!Files.exists(dir)) {
                if (posix) {
                    Files.createDirectories(dir, PosixFilePermissions.asFileAttribute(
                            EnumSet.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE,
                                    PosixFilePermission.OWNER_EXECUTE)));
                } else {
                    Files.createDirectories(dir);
                }
            }
            if (publish(file, fresh.toHex() + "\n", posix)) {
                return fresh;
            }
            // the other process published its secret first: read that one
        }
        return load(file);
    }

    /**
     * Writes {@code text} to a temporary file beside {@code file} (0600 from the start) and gives it
     * {@code file}'s name in one step, unless the name exists by then; {@return whether it was published}.
     * A hard link, not {@code Files.move}: a rename replaces a secret that the other process published
     * meanwhile, and the two would hold different keys; a link fails instead. Where the file system
     * has no hard links, an atomic move after a last look (a narrower race).
     */
    private static boolean publish(Path file, String text, boolean posix) throws IOException {
        Path dir = file.toAbsolutePath().getParent();
        Path tmp = posix ? Files.createTempFile(dir, "." + file.getFileName(), ".tmp", PosixFilePermissions.asFileAttribute(
                EnumSet.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE)))
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

    /** Reads a secret file, refusing one that group or others may read. */
    public static LinkSecret load(Path file) throws IOException {
        if (Files.getFileStore(file).supportsFileAttributeView(PosixFileAttributeView.class)) {
            Set<PosixFilePermission> perms = Files.getPosixFilePermissions(file);
            if (perms.contains(PosixFilePermission.GROUP_READ) || perms.contains(PosixFilePermission.OTHERS_READ)) {
                throw new IOException("the link secret " + file + " may be read by other users; run: chmod 600 " + file);
            }
        }
        String text = Files.readString(file, StandardCharsets.US_ASCII).trim();
        try {
            return fromHex(text);
        } catch (IllegalArgumentException e) {
            throw new IOException(file + ": not a link secret (" + e.getMessage() + ")");
        }
    }

    String toHex() {
        return HexFormat.of().formatHex(key);
    }

    /** {@return HMAC-SHA256 of the parts, in order, under this key} */
    byte[] mac(byte[]... parts) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
            for (byte[] p : parts) {
                mac.update(p);
            }
            return mac.doFinal();
        } catch (NoSuchAlgorithmException | InvalidKeyException e) {
            throw new IllegalStateException("HmacSHA256 is part of every JDK", e);
        }
    }

    /** Never shows the key. */
    @Override
    public String toString() {
        return "LinkSecret[" + key.length + " bytes]";
    }
}
