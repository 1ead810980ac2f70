package jacabot.secret;

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
import java.util.EnumSet;
import java.util.Set;

/**
 * A secret key kept as hex text in a file only its owner may read (mode 0600, its directory 0700),
 * shared by the processes of one user on one machine without setup: the link's secret and the
 * remote workspaces' secret. The file appears whole or not at all, so a process never reads half a
 * key, and two processes making it at once end with the same key (the one that loses reads the
 * other's): no reader waits or retries.
 */
public final class SecretFile {
    private static final Set<PosixFilePermission> OWNER_RW = EnumSet.of(PosixFilePermission.OWNER_READ,
            PosixFilePermission.OWNER_WRITE);
    private static final Set<PosixFilePermission> OWNER_RWX = EnumSet.of(PosixFilePermission.OWNER_READ,
            PosixFilePermission.OWNER_WRITE, PosixFilePermission.OWNER_EXECUTE);

    private SecretFile() {
    }

    /**
     * {@return the key in {@code file} as hex text, trimmed}; when the file does not exist, it is made
     * with {@code freshHex} (which is then what is returned, unless another process made it first).
     *
     * @param what the key's name in messages ({@code "link secret"})
     * @throws IOException when it cannot be read or made, or group or others may read it
     */
    public static String loadOrCreate(Path file, String what, String freshHex) throws IOException {
        if (!Files.exists(file)) {
            Path dir = file.toAbsolutePath().getParent();
            if (!Files.exists(dir)) {
                if (posix(dir.getRoot())) {
                    Files.createDirectories(dir, PosixFilePermissions.asFileAttribute(OWNER_RWX));
                } else {
                    Files.createDirectories(dir);
                }
            }
            if (publish(file, freshHex + "\n")) {
                return freshHex;
            }
            // another process published its key first: read that one
        }
        return read(file, what);
    }

    /**
     * {@return the hex text in {@code file}, trimmed}, refusing a file that group or others may read.
     *
     * @param what the key's name in messages ({@code "link secret"})
     */
    public static String read(Path file, String what) throws IOException {
        if (posix(file)) {
            Set<PosixFilePermission> perms = Files.getPosixFilePermissions(file);
            if (perms.contains(PosixFilePermission.GROUP_READ) || perms.contains(PosixFilePermission.OTHERS_READ)) {
                throw new IOException("the " + what + " " + file + " may be read by other users; run: chmod 600 " + file);
            }
        }
        return Files.readString(file, StandardCharsets.US_ASCII).trim();
    }

    /**
     * Writes {@code text} to a temporary file beside {@code file} (0600 from the start) and gives it
     * {@code file}'s name in one step, unless the name exists by then; {@return whether it was published}.
     * The step is a hard link rather than {@code Files.move(..., ATOMIC_MOVE)}: a rename would replace
     * a key that another process published meanwhile, and the two would hold different keys, while a
     * link fails instead. Where the file system has no hard links, the atomic move after a last look
     * (a narrower race).
     */
    static boolean publish(Path file, String text) throws IOException {
        Path dir = file.toAbsolutePath().getParent();
        String prefix = "." + file.getFileName();
        Path tmp = posix(dir) ? Files.createTempFile(dir, prefix, ".tmp", PosixFilePermissions.asFileAttribute(OWNER_RW))
                : Files.createTempFile(dir, prefix, ".tmp");
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

    private static boolean posix(Path p) throws IOException {
        return Files.getFileStore(p).supportsFileAttributeView(PosixFileAttributeView.class);
    }
}
