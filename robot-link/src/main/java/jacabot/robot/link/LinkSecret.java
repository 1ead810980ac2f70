package jacabot.robot.link;

import jacabot.secret.SecretFile;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.security.InvalidKeyException;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.HexFormat;
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
    /** The secret's name in messages. */
    private static final String NAME = "link secret";
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
     * file appears whole or not at all ({@link SecretFile}), and the one that loses reads the other's.
     *
     * @throws IOException when it cannot be read or made, holds no secret, or group or others may read it
     */
    public static LinkSecret loadOrCreate(Path file) throws IOException {
        return parse(file, SecretFile.loadOrCreate(file, NAME, random().toHex()));
    }

    /** Reads a secret file, refusing one that group or others may read. */
    public static LinkSecret load(Path file) throws IOException {
        return parse(file, SecretFile.read(file, NAME));
    }

    private static LinkSecret parse(Path file, String hex) throws IOException {
        try {
            return fromHex(hex);
        } catch (IllegalArgumentException e) {
            throw new IOException(file + ": not a " + NAME + " (" + e.getMessage() + ")");
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
